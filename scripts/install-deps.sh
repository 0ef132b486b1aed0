#!/usr/bin/env bash
# Installs everything lenslab needs to build, run and test on Debian 12 (see docs in README.md).
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
packages=(
  cmake g++ make ninja-build pkg-config
  libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgbm-dev
  libembree-dev libopenexr-dev libimath-dev libpng-dev libtbb-dev
  libcpp-httplib-dev nlohmann-json3-dev libsqlite3-dev
  libgtest-dev libbenchmark-dev
  openmpi-bin libopenmpi-dev
  libfreetype-dev fonts-dejavu-core
  libopenimageio-dev libassimp-dev zlib1g-dev
  libtiff-dev libraw-dev
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(chromium)
  # libFuzzer with ASan/UBSan for scripts/fuzz.sh (the runtime ships in libclang-rt-14-dev).
  packages+=(clang libclang-rt-14-dev)
  # Node may already come from elsewhere (its npm then conflicts with Debian's npm package).
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
