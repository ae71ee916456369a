# The container must be built by the same scripts CI runs.
file(READ ${DOCKERFILE} text)
foreach(needle "scripts/install-deps.sh" "scripts/build.sh" "HEALTHCHECK" "USER toond")
  string(FIND "${text}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "docker/Dockerfile no longer contains '${needle}'")
  endif()
endforeach()
