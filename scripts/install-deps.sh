#!/usr/bin/env bash
# Installs the Debian packages PRISCA Lab needs to build, test and run.
# (Qt Charts needs the OpenGL module's CMake files, which qt6-charts-dev does not pull in.)
# Quick when nothing is missing: it only asks dpkg, and calls apt-get for what is absent.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    qt6-base-dev qt6-charts-dev libqt6opengl6-dev qt6-serialport-dev
    qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libgl-dev libeigen3-dev libopencv-dev libbox2d-dev libsdl2-dev libnlopt-dev
    gcc-avr avr-libc binutils-avr libsimavr-dev libelf-dev
    xvfb xauth
    clang-format
    qt6-svg-dev qt6-translations-l10n fonts-noto-cjk
    # make package and its checks: manual pages, the .deb's dependencies and lint, the desktop
    # entry and metainfo validators, the completion's framework
    help2man dpkg-dev file lintian desktop-file-utils appstream man-db bash-completion
)
# make fuzz: clang with libFuzzer and its sanitizer runtimes.
if [ "${1:-}" = "fuzz" ]; then
    packages+=(clang libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
    sudo=()
elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
else
    echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo is available" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
