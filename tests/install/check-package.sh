#!/usr/bin/env bash
# Builds the Debian package from a built tree, installs it on this machine (apt resolves its
# dependencies) and uses it as a new user would, from the installed files only: the programs
# on PATH, the manual page, the menu entry and `import pkmstudio` with no PYTHONPATH.
# Needs root (CI runs it after the test suite). Usage: check-package.sh BUILD_DIR
set -euo pipefail
build=$(realpath "$1")
fail() { echo "check-package: $*" >&2; exit 1; }
as_root=()
[[ $(id -u) -eq 0 ]] || as_root=(sudo)

rm -f "$build"/pkm-studio_*.deb
(cd "$build" && cpack -G DEB > cpack.log) || { cat "$build/cpack.log"; fail "cpack -G DEB failed"; }
deb=$(ls "$build"/pkm-studio_*.deb)
echo "check-package: built $(basename "$deb")"
dpkg-deb --field "$deb" Package Version Depends
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y --reinstall --no-install-recommends "$deb" > "$build/apt-install.log" \
    || { cat "$build/apt-install.log"; fail "the package does not install"; }

cd "$(mktemp -d)"
unset PYTHONPATH
[[ $(command -v pkm) == /usr/bin/pkm ]] || fail "pkm is not on PATH from /usr/bin"
pkm list > /dev/null || fail "pkm list failed"
pkm eval pjoint-prototype --json > eval.json || fail "pkm eval pjoint-prototype --json failed"
/usr/bin/python3 -c "import pkmstudio" || fail "import pkmstudio failed"
/usr/bin/python3 - <<'PYTHON' || fail "the installed module does not give pkm's numbers"
import json
import numpy as np
import pkmstudio
assert pkmstudio.__file__.startswith("/usr/lib/python3/dist-packages/"), pkmstudio.__file__
cli = json.load(open("eval.json"))
report = pkmstudio.load("pjoint-prototype").evaluate()
assert np.allclose(report["jacobian"]["J"], np.array(cli["jacobian"]["J"], dtype=float), equal_nan=True)
mapped = pkmstudio.load("moma-3a").map("det", grid=200)
print(f"check-package: pkmstudio from {pkmstudio.__file__}: MOMA 3a det J map {mapped.shape}, {mapped.area:.0f} mm²")
PYTHON
man -w pkm > /dev/null && man -w pkm-studio > /dev/null || fail "man pkm or man pkm-studio is not found"
[[ -f /usr/share/applications/org.pkmstudio.PKMStudio.desktop ]] || fail "the menu entry is not installed"
desktop-file-validate /usr/share/applications/org.pkmstudio.PKMStudio.desktop || fail "the installed menu entry is invalid"
appstreamcli validate --no-net /usr/share/metainfo/org.pkmstudio.PKMStudio.metainfo.xml > /dev/null || fail "the metainfo is invalid"
echo "check-package: installed $(dpkg-query -W -f='${Package} ${Version}' pkm-studio): pkm, man pages, menu entry and Python module work"
