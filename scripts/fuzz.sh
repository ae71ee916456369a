#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan +
# coverage instrumentation, only what they link) and runs each for a bounded
# time from its seed corpus. A crash, a sanitizer report or a broken
# invariant stops with a non-zero status; the input is left in
# BUILD_DIR/findings/<target>/ - copy it to tests/fuzz/regressions/<target>/
# (replayed by ctest) and add a row to tests/bad_inputs/cases.jsonl.
#   scripts/fuzz.sh [SECONDS_PER_TARGET (default 20)] [BUILD_DIR (default build-fuzz)]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
build_dir=${2:-build-fuzz}
targets=(bundle_import render_params multipart gltf_import png_encode)

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DTOOND_TESTS=OFF -DTOOND_BENCH=OFF -DTOOND_FUZZ=ON -DCMAKE_UNITY_BUILD=ON "${launcher[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]/#/fuzz_}" make_gltf_seeds
# The glTF seeds are generated, not stored (tests/fuzz/make_gltf_seeds.cpp).
"$build_dir/tests/fuzz/make_gltf_seeds" "$build_dir/corpus/gltf_import.seeds" >/dev/null

export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
status=0
for t in "${targets[@]}"; do
  work="$build_dir/corpus/$t"       # new inputs land here, not in the repo
  findings="$build_dir/findings/$t"
  mkdir -p "$work" "$findings"
  echo "== fuzz $t for ${seconds}s"
  seeds=("tests/fuzz/corpus/$t")
  if [ "$t" = gltf_import ]; then seeds=("$build_dir/corpus/gltf_import.seeds"); fi
  # Past findings are read too: clang's UBSan here checks what the plain
  # build's replay does not (a float cast past its integer's range).
  if [ -d "tests/fuzz/regressions/$t" ]; then seeds+=("tests/fuzz/regressions/$t"); fi
  if ! "$build_dir/tests/fuzz/fuzz_$t" "$work" "${seeds[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -artifact_prefix="$findings/" -print_final_stats=1 2>"$build_dir/fuzz_$t.log"; then
    tail -40 "$build_dir/fuzz_$t.log"
    echo "fuzz: $t found a problem; the input is in $findings/"
    status=1
  else
    grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "$build_dir/fuzz_$t.log" | tail -2
  fi
done
exit $status
