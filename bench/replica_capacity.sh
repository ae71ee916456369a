#!/usr/bin/env bash
# Renders per second one toond replica sustains for a 512x512 `spot` (the
# capacity figure in docs/deployment.md): starts a replica with the result cache off,
# uploads ../shared/models/spot, then CLIENTS curl loops post
# /models/{id}/render for SECONDS, each request at a slightly different yaw.
#   bench/replica_capacity.sh [SECONDS=20] [CLIENTS=4] [TOOND=build/server/app/toond]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
clients=${2:-4}
toond=${3:-build/server/app/toond}
spot=../shared/models/spot
[ -f "$spot/spot.obj" ] || { echo "needs $spot (the shared models)" >&2; exit 2; }

work=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; rm -rf "$work"' EXIT
"$toond" --listen 127.0.0.1:0 --data-dir "$work/data" --result-cache-mb 0 >"$work/out" 2>"$work/err" &
pid=$!
for _ in $(seq 200); do grep -q '^listening on ' "$work/out" && break; sleep 0.1; done
url=$(sed -n 's/^listening on //p' "$work/out")
[ -n "$url" ] || { cat "$work/err" >&2; exit 1; }

id=$(curl -fsS -F "file=@$spot/spot.obj;filename=spot.obj" -F "file=@$spot/spot.mtl;filename=spot.mtl" \
       -F "file=@$spot/spot_texture.png;filename=spot_texture.png" "$url/models" |
     sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p')
render() {  # yaw
  curl -fsS -o /dev/null -w '%{http_code}\n' -H 'Content-Type: application/json' \
    -d "{\"width\":512,\"height\":512,\"camera\":{\"yaw\":$1}}" "$url/models/$id/render"
}
render 0 >/dev/null  # first use: import, GPU upload, shader compile

end=$(( $(date +%s) + seconds ))
for c in $(seq "$clients"); do
  ( n=0; while [ "$(date +%s)" -lt "$end" ]; do render "$c.$n"; n=$((n + 1)); done ) >"$work/client$c" &
done
wait $(jobs -p | grep -v "^$pid$") 2>/dev/null || true
ok=$(cat "$work"/client* | grep -c '^200$' || true)
failed=$(cat "$work"/client* | grep -vc '^200$' || true)
metrics=$(curl -fsS "$url/metrics")
sum=$(echo "$metrics" | sed -n 's/^toond_render_seconds_sum //p')
count=$(echo "$metrics" | sed -n 's/^toond_render_seconds_count //p')
echo "$(awk -v n="$ok" -v s="$seconds" 'BEGIN{printf "%.1f", n/s}') renders/s" \
     "($ok in ${seconds}s, $clients clients, $failed failed;" \
     "mean request $(awk -v s="$sum" -v c="$count" 'BEGIN{printf "%.0f", 1000*s/c}') ms;" \
     "$(curl -fsS "$url/healthz" | sed -n 's/.*"renderer":"\([^"]*\)".*/\1/p'), $(nproc) CPUs)"
