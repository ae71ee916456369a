#!/usr/bin/env bash
# Configures and builds toond into BUILD_DIR (default build/).
#   scripts/build.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
# Unity batches: each target compiles its sources a batch at a time, so the
# JSON, gtest and std templates they share are compiled once per batch, not
# once per file; a clean build takes half the time (CI builds three trees).
# For one-file-at-a-time incremental work pass -DCMAKE_UNITY_BUILD=OFF.
# compile_commands.json: for scripts/tidy.sh and editors.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
