#!/bin/sh
# The frame and trace benches of two builds side by side, alternated round by round so that load
# from other processes falls on both alike (a slowdown shows as a ratio, not as noise):
#   bench/compare_builds.sh OLD_BUILD NEW_BUILD [rounds=3]
# e.g. a worktree of the previous landed commit built with scripts/build.sh, against build/.
set -eu
old=$1 new=$2 rounds=${3:-3}
for b in "$old" "$new"; do
  for t in bench/optics/bench_trace bench/renderer/frame_cpu_ratios bench/renderer/lenslab_render_bench; do
    [ -x "$b/$t" ] || { echo "missing $b/$t (build the bench targets)" >&2; exit 2; }
  done
done
round=1
while [ "$round" -le "$rounds" ]; do
  for b in "$old" "$new"; do
    echo "=== round $round: $b"
    "$b/bench/optics/bench_trace" 2>/dev/null | grep -E 'Trace ' || true
    "$b/bench/renderer/frame_cpu_ratios" 1 2>/dev/null | tail -n 8
    "$b/bench/renderer/lenslab_render_bench" 2 2>/dev/null | grep '^|' || true
  done
  round=$((round + 1))
done
