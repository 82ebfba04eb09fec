#!/usr/bin/env bash
# From nothing to a running PKM Studio: installs missing Debian packages, builds in Release and
# starts pkm-studio with the active П-joint prototype open. Extra arguments go to pkm-studio
# (a preset id or a design file replaces the prototype).
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache (when installed) keys on paths relative to the clone, so every clone of the project
# shares one cache: a fresh clone rebuilds in minutes, not half an hour.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true

scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target pkm-studio pkm pkm_python
if [[ $# -eq 0 ]]; then
    set -- pjoint-prototype
fi
exec build/bin/pkm-studio "$@"
