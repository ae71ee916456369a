cmake_minimum_required(VERSION 3.20)
# scripts/runtime-packages.sh (what docker/Dockerfile installs in its runtime
# stage) must name the packages of the libraries a binary really links:
# EXPECT lists some that it must name (';'-separated).
execute_process(COMMAND ${SCRIPT} ${BINARY} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "runtime-packages.sh failed (${rc}): ${err}")
endif()
string(REPLACE "\n" ";" packages "${out}")
foreach(package ${EXPECT})
  if(NOT package IN_LIST packages)
    message(FATAL_ERROR "runtime-packages.sh did not name ${package}; it printed:\n${out}")
  endif()
endforeach()
if(out MATCHES "-dev\n")
  message(FATAL_ERROR "runtime-packages.sh named a -dev package:\n${out}")
endif()
