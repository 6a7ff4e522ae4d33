#!/usr/bin/env bash
# Builds the libFuzzer targets (CMake target pcl_tda_fuzzers, which needs clang++) in
# BUILD_DIR and runs each for SECONDS on a copy of its seed corpus. A crash, a leak,
# an input slower than 10 s or over 2 GB fails, printing the end of the log and the
# input that failed (kept in BUILD_DIR/fuzz).
# Usage: test/fuzz/run_fuzzers.sh BUILD_DIR [SECONDS]
set -euo pipefail
build=$(cd "$1" && pwd)
seconds=${2:-30}
here=$(cd "$(dirname "$0")" && pwd)

if ! command -v clang++ > /dev/null; then
  echo "run_fuzzers: clang++ is missing (Debian package clang, see scripts/install_deps.sh)"
  exit 1
fi
cmake --build "$build" --target pcl_tda_fuzzers
cd "$build/fuzz"
for name in pcd_header tool_options; do
  corpus="corpus_$name"
  mkdir -p "$corpus"
  dictionary=()
  if [ -f "$here/$name.dict" ]; then
    dictionary=("-dict=$here/$name.dict")
  fi
  if ! "./fuzz_$name" "${dictionary[@]}" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
      "$corpus" "$here/corpus/$name" > "fuzz_$name.log" 2>&1; then
    echo "fuzz_$name FAILED; the end of $build/fuzz/fuzz_$name.log:"
    tail -n 60 "fuzz_$name.log"
    exit 1
  fi
  echo "fuzz_$name: $(grep -E '^Done|stat::number_of_executed_units' "fuzz_$name.log" | tr '\n' ' ')"
done
