#!/usr/bin/env bash
# The one test command: installs dependencies, builds, and runs every test (unit, integration,
# browser) through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 600
