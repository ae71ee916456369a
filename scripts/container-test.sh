#!/usr/bin/env bash
# The container as users run it, built and checked on every change (called
# by scripts/test.sh, so CI runs it):
#   1. podman builds docker/Dockerfile (--format docker keeps HEALTHCHECK) and
#      reports the image's size per layer;
#   2. one container: /healthz answers within seconds, the daemon runs as
#      uid 10001, the demo renders, a shared model uploads and renders, a
#      Draco .glb and an FBX render (both helpers run in the image as that
#      user), /metrics answers, the health check passes, and after a
#      restart the model is still there (the volume);
#   3. scale-out (scripts/container-scale-test.sh): three replicas and an
#      nginx balancer on one network, sharing one volume.
# Needs podman: ../shared/container/setup.sh installs it (as root) when it is
# missing. Where ../shared is absent, or podman is missing and this is not
# root, the test says it is skipped and why, and exits 0.
#   scripts/container-test.sh [BUILD_DIR (default build; for the Draco test file)]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shared=../shared

skip() { echo "container-test: SKIPPED: $*"; exit 0; }
# podman without systemd says on every run that it cannot schedule the
# health check's timer; the check itself is run by hand below.
quiet_podman() { podman "$@" 2> >(grep -v 'systemd connection' >&2); }
fail() { echo "container-test: FAILED: $*" >&2; exit 1; }

[ -d "$shared/container" ] || skip "$shared/container is absent (podman's set-up script lives there)"
if ! command -v podman >/dev/null 2>&1; then
  [ "$(id -u)" -eq 0 ] || skip "podman is missing and only root can install it ($shared/container/setup.sh)"
  "$shared/container/setup.sh"
fi

image=localhost/toond:container-test
echo "== podman build (docker/Dockerfile)"
started=$SECONDS
podman build --format docker -q -f docker/Dockerfile -t "$image" . >/dev/null
echo "built in $((SECONDS - started)) s; size per layer:"
podman history --format '{{.Size}}\t{{.CreatedBy}}' "$image" | cut -c1-110
echo "image: $(podman image inspect --format '{{.Size}}' "$image" | awk '{printf "%.0f MB", $1 / 1e6}')"

tag=toond-ct-$$
workdir=$(mktemp -d)
cleanup() {
  podman rm -f -t 0 "$tag" >/dev/null 2>&1 || true
  podman volume rm -f "$tag" >/dev/null 2>&1 || true
  rm -rf "$workdir"
}
trap cleanup EXIT

# The URL of a container's port 8080, once /healthz answers (within 30 s).
url_of() {
  local name=$1 address
  for _ in $(seq 300); do
    address=$(podman port "$name" 8080 2>/dev/null | head -n 1 || true)
    if [ -n "$address" ] && curl -fsS -o /dev/null "http://$address/healthz" 2>/dev/null; then
      echo "http://$address"
      return 0
    fi
    sleep 0.1
  done
  podman logs "$name" >&2 || true
  fail "$name: /healthz did not answer within 30 s"
}

is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }

# POST to $1 with the rest as curl arguments; the answer in $workdir/answer,
# the status echoed.
post() {
  local url=$1
  shift
  curl -sS -o "$workdir/answer" -w '%{http_code}' "$@" "$url"
}

# Uploads the files (curl -F arguments) to $1; echoes the model's id.
upload() {
  local url=$1 status
  shift
  status=$(post "$url/models" "$@")
  case $status in 200 | 201) ;; *) fail "upload $*: HTTP $status: $(head -c 300 "$workdir/answer")" ;; esac
  sed -n 's/.*"id":"\([0-9a-f]*\)".*/\1/p' "$workdir/answer"
}

# Renders model $2 on $1 with the JSON request $3; fails unless a PNG comes back.
render() {
  local status
  status=$(post "$1/models/$2/render" -H 'Content-Type: application/json' -d "${3:-{\}}")
  [ "$status" = 200 ] || fail "render of $2 on $1: HTTP $status: $(head -c 300 "$workdir/answer")"
  is_png "$workdir/answer" || fail "render of $2 on $1 is not a PNG"
}

echo "== one container"
podman volume create "$tag" >/dev/null
quiet_podman run -d --name "$tag" -p 127.0.0.1::8080 -v "$tag:/data" "$image" >/dev/null
started=$SECONDS
url=$(url_of "$tag")
echo "/healthz answered after $((SECONDS - started)) s at $url"

uid=$(podman exec "$tag" id -u)
[ "$uid" = 10001 ] || fail "the daemon's user is uid $uid, not 10001"
ps_user=$(podman top "$tag" user comm | awk '$2 == "toond" { print $1 }')
[ "$ps_user" = toond ] || fail "toond runs as '$ps_user', not the user toond"

[ "$(post "$url/render" -H 'Content-Type: application/json' -d '{}')" = 200 ] || fail "POST /render of the demo"
is_png "$workdir/answer" || fail "the demo render is not a PNG"

spot=$shared/models/spot
spot_id=$(upload "$url" -F "file=@$spot/spot.obj" -F "file=@$spot/spot.mtl" -F "file=@$spot/spot_texture.png")
render "$url" "$spot_id" '{"width":128,"height":128}'

"$build_dir/tests/toond-test-draco-sphere" "$workdir/draco.glb"
render "$url" "$(upload "$url" -F "file=@$workdir/draco.glb")"

fbx_id=$(upload "$url" -F "file=@tests/exported/blender/walker.fbx")
grep -q '"name":"Walk"' "$workdir/answer" || fail "the FBX's clips are missing: $(head -c 300 "$workdir/answer")"
render "$url" "$fbx_id" '{"animation":{"clip":"Walk","time":0.25}}'

curl -fsS "$url/metrics" | grep -q '^toond_' || fail "/metrics has no toond_ series"
podman healthcheck run "$tag" >/dev/null || fail "the image's HEALTHCHECK fails"

quiet_podman restart -t 10 "$tag" >/dev/null
url=$(url_of "$tag")
[ "$(curl -sS -o /dev/null -w '%{http_code}' "$url/models/$spot_id")" = 200 ] || fail "spot is gone after a restart"
render "$url" "$spot_id"
echo "one container: all checks passed"

scripts/container-scale-test.sh "$image"
