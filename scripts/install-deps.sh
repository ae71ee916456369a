#!/usr/bin/env bash
# Installs every Debian package toond needs to build, run and test.
# Idempotent: packages already present are left alone. Used by the README's
# commands, by CI (.ci/run) and by docker/Dockerfile, so all three agree.
#   scripts/install-deps.sh [--build-only]
# --build-only (the container's build stage) leaves out what only the tests,
# benchmarks, fuzzing and the browser test need.
set -euo pipefail
build_only=false
if [ "${1:-}" = --build-only ]; then build_only=true; fi

packages=(
  # toolchain
  build-essential cmake pkg-config git ca-certificates curl
  # GL through glvnd (no GLX, no X11 needed at run time) + Mesa's llvmpipe
  libegl-dev libgl-dev libglvnd-dev libegl-mesa0 libgl1-mesa-dri libgbm1
  # scene import, maths, images
  libglm-dev libtinyobjloader-dev libstb-dev libpng-dev zlib1g-dev
  # the PNG stream's Adler-32 (vectorised) and the PNG benchmark's zlib/libdeflate comparison
  libdeflate-dev
  # vertex-cache order and levels of detail at import; glTF's meshopt buffers
  libmeshoptimizer-dev
  # glTF 2.0 / GLB import (JSON and container; images go through our decoders);
  # Draco for KHR_draco_mesh_compression, decoded in the toond-draco-decode helper
  libtinygltf-dev libwebp-dev libdraco-dev
  # FBX, COLLADA, 3DS, 3MF, OFF and more, read by assimp in the
  # toond-assimp-convert helper (the daemon does not link it)
  libassimp-dev
  # HTTP + JSON + schema validation
  libcpp-httplib-dev libssl-dev nlohmann-json3-dev libvalijson-dev
)
test_packages=(
  # tests, shader checks, benchmarks; Pillow decodes our PNGs as a second opinion
  libgtest-dev libgmock-dev glslang-tools libbenchmark-dev python3-pil
  # libFuzzer targets (scripts/fuzz.sh): clang and its fuzzer runtime
  clang libclang-rt-14-dev
  # the one code format, checked by CI (scripts/check-format.sh); the checks
  # of .clang-tidy (scripts/tidy.sh); functions measured by ctags
  # (tests/check_sizes.py)
  clang-format clang-tidy universal-ctags
  # the scale-out test's load balancer (tests/integration/scale_out_test.cpp)
  nginx-light
  # the web page's browser test: Debian's chromium driven by playwright-core from npm
  chromium
  # output svg's drawings rasterised by an independent reader, librsvg
  # (tests/integration/svg_output_test.cpp)
  librsvg2-bin
)

if ! $build_only; then packages+=("${test_packages[@]}"); fi

# Node.js and npm are wanted as commands, not as Debian packages: machines that
# already carry NodeSource's nodejs (which bundles npm) cannot also take Debian's
# npm package ("held broken packages"), so Debian's pair is installed only where
# the commands are missing.
if ! $build_only && { ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; }; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
