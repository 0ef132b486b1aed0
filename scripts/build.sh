#!/usr/bin/env bash
# Configures and builds lenslab into build/ (Release). Extra arguments go to cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
# Ninja for a new build folder when it is installed (ninja-build); an existing folder keeps the
# generator it was made with.
generator=()
[ -f build/CMakeCache.txt ] || ! command -v ninja >/dev/null || generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"${LENSLAB_JOBS:-2}"
