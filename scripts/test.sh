#!/usr/bin/env bash
# The one test command: installs dependencies, builds, and runs every test (unit, integration,
# browser) through CTest, then a short fuzz run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
scripts/build.sh
# The fuzz targets' own build (clang, ASan) runs beside the tests at the lowest priority: the tests
# leave about 40% of the two cores idle while they wait on the service and Chromium, and at nice 19
# the compiler gets only that.
# Its own process group (setsid), so that a failing ctest stops the whole build too.
setsid nice -n 19 scripts/fuzz.sh --build-only >build/fuzz-build.log 2>&1 &
fuzz_build=$!
trap 'kill -- -$fuzz_build 2>/dev/null || true' EXIT
ctest --test-dir build --output-on-failure -j2 --timeout 600
wait $fuzz_build || { cat build/fuzz-build.log; exit 1; }
# A short fuzz of five parsers and the tracer (lens table, trace, .zmx, .seq, .agf, NanoVDB; 10 s
# each: a smoke run that keeps the whole test within its time; longer runs: scripts/fuzz.sh 300).
scripts/fuzz.sh 10
