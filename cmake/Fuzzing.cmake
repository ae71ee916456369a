# -DTOOND_FUZZ=ON (clang only): every first-party target is built with
# libFuzzer's coverage instrumentation plus ASan and UBSan, and the fuzz
# targets of tests/fuzz are added. scripts/fuzz.sh makes such a build.
option(TOOND_FUZZ "Build the libFuzzer targets of tests/fuzz (clang only)" OFF)
if(TOOND_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "TOOND_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++); this is ${CMAKE_CXX_COMPILER_ID}")
  endif()
  target_compile_options(toond_warnings INTERFACE -fsanitize=fuzzer-no-link,address,undefined
    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(toond_warnings INTERFACE -fsanitize=address,undefined)
endif()
