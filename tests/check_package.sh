#!/usr/bin/env bash
# The Debian package as a lab installs it (docs/install.md): CPack on this build, lintian with no
# error, the files where they belong, the desktop entry and the metainfo valid, both manual pages
# rendered with every command in prisca-cli's, the completion answering, and the extracted
# programs running (--version, doctor --format json) with no source tree in sight.
#   check_package.sh BUILD_DIR VERSION
set -euo pipefail
build=$1
version=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "check_package: $*" >&2; exit 1; }

for tool in cpack lintian dpkg-deb desktop-file-validate appstreamcli man bash; do
    command -v "$tool" >/dev/null || fail "$tool is missing (scripts/install-deps.sh installs it)"
done

(cd "$build" && cpack -G DEB -B "$work/out" >"$work/cpack.log" 2>&1) ||
    { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/out/prisca-lab_"$version"-1_*.deb 2>/dev/null) ||
    fail "no prisca-lab_$version-1_<arch>.deb in $(ls "$work/out")"

lintian "$deb" >"$work/lintian.txt" 2>&1 || true
grep -v 'running with root privileges' "$work/lintian.txt" || true
if grep -q '^E: ' "$work/lintian.txt"; then fail "lintian reports errors (above)"; fi
if grep -q '^W: ' "$work/lintian.txt"; then
    fail "lintian warnings (above): fix them or override each with its reason"
fi

control=$(dpkg-deb -f "$deb")
for field in "Package: prisca-lab" "Version: $version-1" "Depends: .*libqt6core6" \
    "Depends: .*qt6-qpa-plugins" "Maintainer: "; do
    grep -q "^$field" <<<"$control" || fail "control has no '$field':
$control"
done

root=$work/root
dpkg-deb -x "$deb" "$root"
id=lab.prisca.PriscaLab
for file in usr/bin/prisca usr/bin/prisca-cli \
    usr/share/applications/$id.desktop usr/share/metainfo/$id.metainfo.xml \
    usr/share/icons/hicolor/16x16/apps/$id.png usr/share/icons/hicolor/256x256/apps/$id.png \
    usr/share/icons/hicolor/scalable/apps/$id.svg \
    usr/share/man/man1/prisca.1.gz usr/share/man/man1/prisca-cli.1.gz \
    usr/share/bash-completion/completions/prisca-cli usr/lib/udev/rules.d/70-prisca-lab.rules \
    usr/share/doc/prisca-lab/copyright usr/share/doc/prisca-lab/changelog.Debian.gz \
    usr/share/doc/prisca-lab/operator-guide.md usr/share/doc/prisca-lab/install.md; do
    [ -f "$root/$file" ] || fail "the package has no /$file"
done
if [ -f "$build/devices/firmware/ppm_bridge.hex" ]; then  # built where avr-gcc is
    [ -f "$root/usr/share/prisca-lab/firmware/ppm_bridge.hex" ] || fail "no firmware in the package"
    grep -q '^:00000001FF' "$root/usr/share/prisca-lab/firmware/ppm_bridge.hex" ||
        fail "the firmware is not an Intel hex file"
fi

out=$(desktop-file-validate "$root/usr/share/applications/$id.desktop" 2>&1) ||
    fail "desktop-file-validate: $out"
[ -z "$out" ] || fail "desktop-file-validate says: $out"
appstreamcli validate --no-net "$root/usr/share/metainfo/$id.metainfo.xml" >"$work/as.txt" 2>&1 ||
    { cat "$work/as.txt"; fail "appstreamcli validate failed"; }
if grep -q '^[EW]: ' "$work/as.txt"; then cat "$work/as.txt"; fail "metainfo errors or warnings"; fi

for page in prisca prisca-cli; do
    MANWIDTH=100 man -l "$root/usr/share/man/man1/$page.1.gz" >"$work/$page.txt" 2>"$work/$page.err" ||
        fail "man -l $page.1.gz failed: $(cat "$work/$page.err")"
    [ ! -s "$work/$page.err" ] || fail "man -l $page.1.gz warns: $(cat "$work/$page.err")"
    grep -q "$version" "$work/$page.txt" || fail "$page(1) does not give the version"
done
for command in $("$root/usr/bin/prisca-cli" --help | sed -n '/^Commands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'); do
    grep -q "^   $command\$\|^   $command " "$work/prisca-cli.txt" ||
        fail "prisca-cli(1) has no section for the command '$command'"
done
grep -q 'E-STOP' "$work/prisca.txt" || fail "prisca(1) does not say how to stop"

complete() {  # the completions bash offers for the words given, the last one being completed
    bash -c 'source /usr/share/bash-completion/bash_completion
             source "$1"; shift
             COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
             _prisca_cli; printf "%s\n" "${COMPREPLY[@]}"' _ \
        "$root/usr/share/bash-completion/completions/prisca-cli" "$@"
}
[ -f /usr/share/bash-completion/bash_completion ] || fail "bash-completion is not installed"
grep -qx run <<<"$(complete prisca-cli ru)" || fail "prisca-cli ru<TAB> does not offer run"
grep -qx doctor <<<"$(complete prisca-cli do)" || fail "prisca-cli do<TAB> does not offer doctor"
grep -qx -- --method <<<"$(complete prisca-cli run --me)" || fail "run --me<TAB>: no --method"
grep -qx mpc <<<"$(complete prisca-cli run --method m)" || fail "--method m<TAB>: no mpc"
grep -qx slidecar <<<"$(complete prisca-cli demo --plant s)" || fail "--plant s<TAB>: no slidecar"
grep -qx prisca.H= <<<"$(complete prisca-cli run --param prisca.)" || fail "--param: no prisca.H="

# The programs from the package, in an empty home, far from the build and the sources.
unset XDG_DATA_HOME XDG_CONFIG_HOME XDG_CACHE_HOME
home=$work/home
mkdir -p "$home"
cd "$home"
got=$(HOME=$home "$root/usr/bin/prisca-cli" --version)
[ "$got" = "prisca-cli $version" ] || fail "prisca-cli --version says '$got'"
got=$(HOME=$home env -u DISPLAY -u WAYLAND_DISPLAY "$root/usr/bin/prisca" --version)
[ "$got" = "prisca $version" ] || fail "prisca --version (no display) says '$got'"
status=0
HOME=$home "$root/usr/bin/prisca-cli" doctor --format json >"$work/doctor.json" || status=$?
[ "$status" -le 1 ] || fail "prisca-cli doctor exited $status"
grep -q '"items"' "$work/doctor.json" && grep -q '"ready"' "$work/doctor.json" ||
    fail "doctor --format json: $(cat "$work/doctor.json")"
grep -q "\"bundles\": \"$home/.local/share/PRISCA Lab/prisca/trials\"" "$work/doctor.json" ||
    fail "doctor does not place the bundles under the XDG data folder: $(cat "$work/doctor.json")"
echo "check_package: $(basename "$deb") holds what a lab installs; lintian, the validators and the manual pages agree"
