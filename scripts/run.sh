#!/usr/bin/env bash
# The one run command: installs dependencies, builds, and starts the lenslab service on
# 127.0.0.1 (port $PORT, default 8080) with the bundled lenses and scenes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec build/cli/lenslab serve --host 127.0.0.1 --port "${PORT:-8080}" --data "${LENSLAB_DATA:-data}" "$@"
