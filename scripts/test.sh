#!/usr/bin/env bash
# The one test command: installs dependencies, builds, and runs every test (unit, integration,
# browser) through CTest, then a short fuzz run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 600
# A short fuzz of five parsers and the tracer (lens table, trace, .zmx, .seq, .agf, NanoVDB; 10 s
# each: a smoke run that keeps the whole test within its time; longer runs: scripts/fuzz.sh 300).
scripts/fuzz.sh 10
