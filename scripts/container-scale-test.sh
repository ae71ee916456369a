#!/usr/bin/env bash
# Scale-out with real containers: three toond replicas and an nginx balancer
# (docker/balancer/Dockerfile: Debian's nginx with docker/nginx/) on one
# podman network, the replicas sharing one volume, as docker/compose.yaml
# deploys them. Checks that a model's renders through the balancer land on
# one replica (each replica's /metrics counts the renders it served), that
# an upload through one replica is served by every replica, and that with
# the serving replica stopped every request through the balancer still
# succeeds. Called by scripts/container-test.sh with the image it built.
#   scripts/container-scale-test.sh IMAGE
set -euo pipefail
cd "$(dirname "$0")/.."
image=${1:?usage: scripts/container-scale-test.sh IMAGE}
# podman without systemd says on every run that it cannot schedule the
# health check's timer; the check itself is run by hand below.
quiet_podman() { podman "$@" 2> >(grep -v 'systemd connection' >&2); }
fail() { echo "container-scale-test: FAILED: $*" >&2; exit 1; }

tag=toond-cs-$$
balancer_image=localhost/toond-balancer:container-test
workdir=$(mktemp -d)
cleanup() {
  podman rm -f -t 0 "$tag-balancer" "$tag-1" "$tag-2" "$tag-3" >/dev/null 2>&1 || true
  podman network rm -f "$tag" >/dev/null 2>&1 || true
  podman volume rm -f "$tag" >/dev/null 2>&1 || true
  rm -rf "$workdir"
}
trap cleanup EXIT

echo "== scale-out: three replicas behind nginx"
podman build -q -f docker/balancer/Dockerfile -t "$balancer_image" . >/dev/null
podman network create "$tag" >/dev/null
podman volume create "$tag" >/dev/null
for n in 1 2 3; do
  # Every replica answers to the name `toond` on the network, as compose's
  # service name does; nginx resolves it to all three when it starts.
  quiet_podman run -d --name "$tag-$n" --network "$tag" --network-alias toond -v "$tag:/data" \
    -p 127.0.0.1::8080 "$image" >/dev/null
done

wait_for() {  # URL PATH: until it answers 200, at most 30 s
  for _ in $(seq 300); do
    curl -fsS -o /dev/null "$1$2" 2>/dev/null && return 0
    sleep 0.1
  done
  fail "$1$2 did not answer within 30 s"
}
replica_url() { echo "http://$(podman port "$tag-$1" 8080 | head -n 1)"; }
for n in 1 2 3; do wait_for "$(replica_url "$n")" /healthz; done
quiet_podman run -d --name "$tag-balancer" --network "$tag" -p 127.0.0.1::8080 "$balancer_image" >/dev/null
balancer="http://$(podman port "$tag-balancer" 8080 | head -n 1)"
wait_for "$balancer" /healthz

post() {  # URL [curl args]: the status; the answer in $workdir/answer
  local url=$1
  shift
  curl -sS -o "$workdir/answer" -w '%{http_code}' "$@" "$url"
}
upload() {  # URL [curl -F args]: the model id
  local url=$1 status
  shift
  status=$(post "$url/models" "$@")
  case $status in 200 | 201) ;; *) fail "upload to $url: HTTP $status: $(head -c 300 "$workdir/answer")" ;; esac
  sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p' "$workdir/answer"
}
render_status() { post "$1/models/$2/render" -H 'Content-Type: application/json' -d '{"width":96,"height":96}'; }
# The renders of /models/{id}/render that replica N has answered 200.
renders_served() {
  curl -fsS "$(replica_url "$1")/metrics" |
    awk '/^toond_http_requests_total\{/ && /route="\/models\/\{id\}\/render"/ && /status="200"/ && /method="POST"/ { s += $NF } END { print s + 0 }'
}

spot=../shared/models/spot
id=$(upload "$balancer" -F "file=@$spot/spot.obj" -F "file=@$spot/spot.mtl" -F "file=@$spot/spot_texture.png")
declare -a before
for n in 1 2 3; do before[n]=$(renders_served "$n"); done
for _ in $(seq 12); do [ "$(render_status "$balancer" "$id")" = 200 ] || fail "render through the balancer"; done
serving=""
for n in 1 2 3; do
  served=$(($(renders_served "$n") - before[n]))
  echo "replica $n served $served of 12 renders of $id"
  if [ "$served" -eq 12 ]; then serving=$n; elif [ "$served" -ne 0 ]; then fail "the renders of one model were split"; fi
done
[ -n "$serving" ] || fail "no replica served all 12 renders of $id"

# An upload through one replica is served by all (the shared volume).
cube=$(upload "$(replica_url 1)" -F "file=@tests/exported/blender/textured.glb")
for n in 1 2 3; do
  [ "$(render_status "$(replica_url "$n")" "$cube")" = 200 ] || fail "replica $n cannot render a model uploaded through replica 1"
done

# The serving replica stops: every request through the balancer still succeeds.
quiet_podman stop -t 5 "$tag-$serving" >/dev/null
for _ in $(seq 12); do
  [ "$(render_status "$balancer" "$id")" = 200 ] || fail "a render failed with replica $serving stopped"
  [ "$(render_status "$balancer" "$cube")" = 200 ] || fail "a render failed with replica $serving stopped"
done
[ "$(post "$balancer/render" -H 'Content-Type: application/json' -d '{}')" = 200 ] || fail "POST /render with a replica stopped"
echo "scale-out: all checks passed (replica $serving stopped, every request answered)"
