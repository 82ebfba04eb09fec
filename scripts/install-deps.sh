#!/usr/bin/env bash
# Installs the Debian 12 packages PKM Studio needs to build, test and run — only those that
# are missing, so it is quick when everything is there already.
set -euo pipefail

packages=(
    g++ cmake ninja-build ccache pkg-config
    qt6-base-dev qt6-base-dev-tools qt6-qpa-plugins qt6-svg-dev
    qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
    libeigen3-dev libqcustomplot-dev libgl-dev libqt6opengl6-dev libgl1-mesa-dri libgif-dev
    libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
    xvfb xauth
    fonts-dejavu-core locales
    python3-numpy
    python3-ezdxf
    poppler-utils
    desktop-file-utils appstream man-db   # the install checks: desktop entry, AppStream metadata, manual pages
    clang libclang-rt-14-dev
    pybind11-dev python3-dev python3-pytest python3-matplotlib
)

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
if [[ ${#missing[@]} -eq 0 ]]; then
    exit 0
fi

echo "Installing missing Debian packages: ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
    as_root=()
elif command -v sudo >/dev/null; then
    as_root=(sudo)
else
    echo "error: these packages are missing and neither root nor sudo is available: ${missing[*]}" >&2
    echo "       install them as root: apt-get install ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update
"${as_root[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
