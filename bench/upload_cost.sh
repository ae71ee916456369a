#!/usr/bin/env bash
# What the import benchmark's mesh costs through the daemon: the same mesh
# as OBJ and as GLB (made by toond_import_bench --write), each uploaded to a
# fresh toond with curl -F (POST /models) REPEATS times, the two formats
# taking turns. Every upload's model is deleted before the next, since an
# upload the store already holds is not imported again. Prints per format
# the bytes, the median request time curl saw, and the median import time
# the daemon measured itself (the growth of toond_import_seconds_sum: the
# import and the durable store, without the transfer).
#   bench/upload_cost.sh [REPEATS=5] [SEGMENTS=640] [BUILD=build]
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-5}
segments=${2:-640}
build=${3:-build}
toond=$build/server/app/toond
import_bench=$build/bench/toond_import_bench
for binary in "$toond" "$import_bench"; do
  [ -x "$binary" ] || { echo "needs $binary (scripts/build.sh $build -DTOOND_TESTS=ON)" >&2; exit 2; }
done

work=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && { kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; }; rm -rf "$work"' EXIT
"$import_bench" --segments "$segments" --repeats 1 --write "$work/files" | head -1
"$toond" --listen 127.0.0.1:0 --data-dir "$work/data" >"$work/out" 2>"$work/err" &
pid=$!
for _ in $(seq 300); do grep -q '^listening on ' "$work/out" && break; sleep 0.1; done
url=$(sed -n 's/^listening on //p' "$work/out")
[ -n "$url" ] || { cat "$work/err" >&2; exit 1; }

import_sum() { curl -fsS "$url/metrics" | sed -n 's/^toond_import_seconds_sum //p'; }
upload() {  # file; appends "curl seconds, import seconds" to $work/<file>.times
  local before after answer id
  before=$(import_sum)
  answer=$(curl -fsS -w '\n%{time_total}' -F "file=@$work/files/$1;filename=$1" "$url/models")
  after=$(import_sum)
  id=$(echo "$answer" | head -1 | sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p')
  [ -n "$id" ] || { echo "upload of $1 failed: $answer" >&2; exit 1; }
  echo "$answer" | tail -1 | awk -v a="$after" -v b="$before" '{ print $1, a - b }' >>"$work/$1.times"
  curl -fsS -X DELETE "$url/models/$id" >/dev/null
}
median() {  # column; the middle value (the lower middle for an even count)
  sort -g -k"$1" | awk -v c="$1" '{ v[NR] = $c } END { printf "%.0f", 1000 * v[int((NR + 1) / 2)] }'
}

for _ in $(seq "$repeats"); do
  upload sphere.obj
  upload model.glb
done
printf '%-10s %12s %16s %18s\n' format bytes "curl total ms" "daemon import ms"
for file in sphere.obj model.glb; do
  printf '%-10s %12s %16s %18s\n' "${file##*.}" "$(stat -c %s "$work/files/$file")" \
    "$(median 1 <"$work/$file.times")" "$(median 2 <"$work/$file.times")"
done
echo "medians of $repeats uploads each, $url"
