#!/usr/bin/env bash
# The suite's load test (tests/hostile/load_test.cpp: 16 clients mixing
# renders, uploads and bad requests against one daemon with --queue 4) run
# for longer: zero 5xx but 503, every PNG valid, RSS flat after warm-up.
#   scripts/load_test.sh [SECONDS (default 30)] [BUILD_DIR (default build)]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
build_dir=${2:-build}
cmake --build "$build_dir" -j "$(nproc)" --target toond toond_hostile_tests
TOOND_LOAD_SECONDS="$seconds" "$build_dir/tests/hostile/toond_hostile_tests" \
  --gtest_filter='Load.*' --gtest_color=no
