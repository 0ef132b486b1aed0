#!/bin/bash
# The as-built Cooke triplet seen: Monte Carlo tolerancing (cooke-tolerances.json, 1000 trials,
# seed 1) writes the 90th-percentile trial's lens; both it and the nominal lens then render the
# slanted-edge chart at every field (bench_slanted_edge: each edge's e-SFR from the render against
# the analysis's MTF times the pixel's):
#   bench/design/as_built_slanted_edge.sh [BUILD=build] [OUTDIR=/tmp/as-built] [SPP=16]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build} out=${2:-/tmp/as-built} spp=${3:-16}
mkdir -p "$out"
"$build/cli/lenslab" tolerance lenses/design/cooke-triplet-50mm.zmx --merit bench/design/cooke-merit.json \
  --spec bench/design/cooke-tolerances.json --trials 1000 --seed 1 -o "$out" | grep -E '^wrote|yield'
"$build/bench/report/bench_slanted_edge" "$out" --spp "$spp" lenses/design/cooke-triplet-50mm.zmx 5.6 "$out/p90.zmx" 5.6
