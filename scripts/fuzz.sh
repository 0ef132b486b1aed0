#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) in build-fuzz/ and runs each for SECONDS
# (default 60) on a scratch copy of tests/fuzz/corpus/<target>; new inputs stay in the copy.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: lens_table trace zemax codev agf nanovdb; default all)
# Exits 0 without fuzzing when clang or its libFuzzer runtime is missing; non-zero on a finding,
# whose reproducer is left in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(lens_table trace zemax codev agf nanovdb)

if ! command -v clang++ >/dev/null ||
   ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
     clang++ -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  echo "fuzz.sh: clang++ with libFuzzer not available; skipping (scripts/install-deps.sh --tests installs it)"
  exit 0
fi

generator=()
[ -f build-fuzz/CMakeCache.txt ] || ! command -v ninja >/dev/null || generator=(-G Ninja)
CC=clang CXX=clang++ cmake -S . -B build-fuzz "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLENSLAB_FUZZ=ON \
  -DLENSLAB_BUILD_BENCH=OFF -DLENSLAB_NATIVE=OFF >/dev/null
cmake --build build-fuzz -j"${LENSLAB_JOBS:-2}" --target "${targets[@]/#/fuzz_}"

rm -rf build-fuzz/findings
mkdir -p build-fuzz/findings
# Fuzzes one target; prints its statistics, or its log's tail and where the reproducer is.
fuzz_one() {
  local t=$1 work="build-fuzz/corpus-$1" log="build-fuzz/fuzz-$1.log"
  rm -rf "$work"
  cp -r "tests/fuzz/corpus/$t" "$work"
  # -timeout: an input taking 10 s counts as a hang; -rss_limit_mb catches runaway allocation.
  if ! build-fuzz/tests/fuzz/fuzz_"$t" "$work" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=4096 -print_final_stats=1 -artifact_prefix=build-fuzz/findings/"$t"- >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz.sh: fuzz_$t found a problem; reproducer in build-fuzz/findings/"
    return 1
  fi
  echo "fuzz.sh: fuzz_$t for ${seconds}s (log: $log)"
  grep -E '^(Done|stat::)' "$log"
}

# As many targets at once as the build uses cores (each fuzzer is one process on one core).
jobs_at_once="${LENSLAB_JOBS:-2}"
failed=0
for ((i = 0; i < ${#targets[@]}; i += jobs_at_once)); do
  pids=()
  for t in "${targets[@]:i:jobs_at_once}"; do
    fuzz_one "$t" >"build-fuzz/fuzz-$t.out" 2>&1 &
    pids+=($!)
  done
  for j in "${!pids[@]}"; do
    wait "${pids[$j]}" || failed=1
    cat "build-fuzz/fuzz-${targets[$((i + j))]}.out"
  done
done
exit "$failed"
