#!/usr/bin/env bash
# `cmake --install` into a scratch prefix, then what a user of the installed files does: the
# programs run from there (pkm finds its drawing half in libexec), the Python module imports
# from dist-packages, the desktop entry and the AppStream metadata validate, and the manual
# pages render. Usage: check-install.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
build=$1
scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
DESTDIR="$scratch" cmake --install "$build" --prefix /usr > "$scratch/install.log"
usr="$scratch/usr"
fail() { echo "check-install: $*" >&2; exit 1; }

for file in bin/pkm bin/pkm-studio libexec/pkm-studio/pkm-draw \
    share/applications/org.pkmstudio.PKMStudio.desktop share/metainfo/org.pkmstudio.PKMStudio.metainfo.xml \
    share/icons/hicolor/scalable/apps/pkm-studio.svg share/mime/packages/pkm-studio.xml \
    share/man/man1/pkm.1 share/man/man1/pkm-studio.1 share/pkm-studio/presets/pjoint-prototype.pkm.json \
    share/pkm-studio/translations/pkm_studio_ru.qm share/doc/pkm-studio/copyright; do
    [[ -e "$usr/$file" ]] || fail "cmake --install did not install $file"
done
module=$(ls "$usr"/lib/python3/dist-packages/pkmstudio/_core*.so 2>/dev/null | head -1)
[[ -n "$module" ]] || fail "cmake --install did not install the Python module"

# the installed programs, away from the build tree
cd "$scratch"
"$usr/bin/pkm" list > /dev/null || fail "the installed pkm list failed"
"$usr/bin/pkm" eval pjoint-prototype --json | /usr/bin/python3 -c "import json, sys; json.load(sys.stdin)" \
    || fail "the installed pkm eval --json failed"
"$usr/bin/pkm" render pjoint-prototype -o "$scratch/prototype.png" > /dev/null \
    || fail "the installed pkm does not find pkm-draw in libexec/pkm-studio"
"$usr/bin/pkm" eval "$usr/share/pkm-studio/presets/moma-3a.pkm.json" > /dev/null || fail "an installed preset file does not load"
QT_QPA_PLATFORM=offscreen "$usr/bin/pkm-studio" --version > /dev/null 2>&1 || fail "the installed pkm-studio --version failed"
PYTHONPATH="$usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import pkmstudio; assert pkmstudio.load('moma-3a').map('det', grid=50).reachable_cells > 0" \
    || fail "the installed Python module does not work"

desktop-file-validate "$usr/share/applications/org.pkmstudio.PKMStudio.desktop" || fail "desktop-file-validate failed"
appstreamcli validate --no-net "$usr/share/metainfo/org.pkmstudio.PKMStudio.metainfo.xml" || fail "appstreamcli validate failed"
for page in pkm pkm-studio; do
    text=$(MANWIDTH=80 man -l "$usr/share/man/man1/$page.1" 2>&1) || fail "man -l $page.1 failed"
    grep -q -- "--help" <<< "$text" || fail "$page.1 does not list the options"
done
grep -q "pkm eval" <<< "$(MANWIDTH=80 man -l "$usr/share/man/man1/pkm.1")" || fail "pkm.1 has no commands"
echo "check-install: every file in place, the installed programs and module work"
