#!/usr/bin/env bash
# Runs clang-tidy with the repository's .clang-tidy over every first-party
# translation unit of a configured build (its compile_commands.json, which
# scripts/build.sh always writes): the daemon, its helpers, the shared
# libraries, the wire schema's reader, the CLI and the benchmarks. A unity
# build's batches are checked as they are compiled, a batch at a time, so a
# file is parsed once. Any finding fails the run; the whole log is left in
# BUILD_DIR/tidy.log.
#   scripts/tidy.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
if [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "tidy: $build_dir/compile_commands.json is missing: configure with scripts/build.sh first" >&2
  exit 2
fi
root=$(pwd)
# The translation units of the first-party targets: their own sources, or
# the unity batches that include them; not the tests'.
mapfile -t units < <(python3 - "$build_dir/compile_commands.json" "$root" <<'PY'
import json, os, re, sys
commands, root = sys.argv[1], sys.argv[2]
first_party = re.compile(r'/(common|server|client|proto|bench)/')
for entry in json.load(open(commands)):
    path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
    relative = os.path.relpath(path, root)
    if first_party.search("/" + relative) and "/tests/" not in "/" + relative:
        print(path)
PY
)
echo "tidy: ${#units[@]} translation units, $(nproc) at a time"
# -Wno-unknown-warning-option: the build is GCC's; its warning flags that
# clang does not know are not findings.
printf '%s\n' "${units[@]}" | xargs -P "$(nproc)" -n 1 \
  clang-tidy -p "$build_dir" --quiet --extra-arg=-Wno-unknown-warning-option > "$build_dir/tidy.log" 2>&1 || true
# Each finding is "file:line:col: error: ... [check]"; a unity batch reports
# the files it includes, so one finding may come from two batches.
if grep -E ': (error|warning): .*\[[a-z0-9.,-]+\]$' "$build_dir/tidy.log" | sort -u > "$build_dir/tidy.findings"; then
  echo "tidy: $(wc -l < "$build_dir/tidy.findings") findings (.clang-tidy):" >&2
  cat "$build_dir/tidy.findings" >&2
  exit 1
fi
if grep -qE 'Error while processing|Segmentation fault|crashed' "$build_dir/tidy.log"; then
  echo "tidy: clang-tidy failed on a translation unit:" >&2
  grep -E 'Error while processing|Segmentation fault|crashed' "$build_dir/tidy.log" >&2
  exit 1
fi
echo "tidy: no findings"
