#!/usr/bin/env bash
# Wall time of one frame rendered by 1 process (plain `lenslab render`) and by mpirun with 2, 3, 4
# processes (rank 0 schedules, the others render; --bind-to none so the workers share the cores),
# for several image sizes; the best of REPEATS runs. Prints a markdown table (docs/scaling.md).
# Usage: bench/mpi/scaling.sh [build dir] [scene] [spp]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
scene=${2:-scenes/pbrt-v3-dgauss50.pbrt}
spp=${3:-16}
repeats=${REPEATS:-3}
lenslab="$build/cli/lenslab"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

best() {  # best wall seconds of "$@" over the repeats
  local best=""
  for _ in $(seq "$repeats"); do
    local t0 t1
    t0=$(date +%s.%N)
    "$@" > /dev/null 2>&1
    t1=$(date +%s.%N)
    best=$(echo "$t0 $t1 ${best:-1e9}" | awk '{d = $2 - $1; print (d < $3 ? d : $3)}')
  done
  echo "$best"
}

echo "| pixels | 1 process (s) | np 2 (s) | np 3 (s) | np 4 (s) | speed-up np 3 |"
echo "|---|---|---|---|---|---|"
for side in 64 128 256 400; do
  args=(render "$scene" --spp "$spp" --width "$side" --height "$side" --seed 7 --quiet -o "$out/i.exr")
  t1=$(best "$lenslab" "${args[@]}")
  row="| ${side}x${side} | $(printf %.2f "$t1")"
  for np in 2 3 4; do
    t=$(best mpirun --allow-run-as-root --oversubscribe --bind-to none -np "$np" "$lenslab" "${args[@]}" --mpi)
    row+=" | $(printf %.2f "$t")"
    [ "$np" = 3 ] && t3=$t
  done
  echo "$row | $(echo "$t1 $t3" | awk '{printf "%.2f", $1 / $2}') |"
done
