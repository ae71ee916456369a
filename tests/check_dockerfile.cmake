# The container must be built by the same scripts CI runs, and keep what the
# deployment relies on (docs/deployment.md, "Deploying", docker/README.md).
file(READ ${DOCKERFILE} text)
# Instructions only: a needle left in a comment does not count.
string(REGEX REPLACE "(^|\n)[ \t]*#[^\n]*" "\\1" text "${text}")
foreach(needle
    "RUN scripts/install-deps.sh"   # the packages CI installs
    "scripts/build.sh"              # the build CI runs
    "scripts/runtime-packages.sh"   # runtime libraries derived from the binaries
    "toond-draco-decode"            # the helpers toond runs from its own folder
    "toond-assimp-convert"
    "libegl-mesa0"                  # Mesa's EGL vendor: llvmpipe without a GPU
    "libegl1"                       # glvnd's libEGL: NVIDIA's EGL on a GPU host
    "NVIDIA_DRIVER_CAPABILITIES=graphics,utility"
    "HEALTHCHECK"
    "\"toon\", \"--server\", \"http://127.0.0.1:8080\", \"health\""  # GET /healthz
    "USER toond"
    "VOLUME /data")
  string(FIND "${text}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "docker/Dockerfile no longer contains '${needle}'")
  endif()
endforeach()
# The runtime stage starts from a bare Debian and copies binaries only, never
# the build tree or the toolchain.
string(REGEX MATCH "FROM debian:12 AS runtime.*" runtime "${text}")
if(runtime STREQUAL "")
  message(FATAL_ERROR "docker/Dockerfile has no 'FROM debian:12 AS runtime' stage")
endif()
string(REGEX MATCHALL "COPY --from=build [^\n]*" copies "${runtime}")
foreach(copy IN LISTS copies)
  if(NOT copy MATCHES "^COPY --from=build /out/")
    message(FATAL_ERROR "runtime stage copies more than the binaries: ${copy}")
  endif()
endforeach()
if(runtime MATCHES "build-essential|-dev[ \n]")
  message(FATAL_ERROR "runtime stage installs build tools or -dev packages")
endif()
