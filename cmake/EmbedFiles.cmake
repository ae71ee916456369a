# toond_embed_files(TARGET NAMESPACE FILES...)
# Turns text files into a static library exposing
#   std::string_view <NAMESPACE>::find(std::string_view name)
#   std::span<const <NAMESPACE>::Entry> <NAMESPACE>::all()
# so shaders, the wire schema and the web page live inside the binaries and a
# deployed daemon never depends on its source tree. The generated source is
# rebuilt whenever one of the inputs changes.
set(TOOND_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_generate.cmake)

function(toond_embed_files target namespace)
  set(out_cpp ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  set(out_h ${CMAKE_CURRENT_BINARY_DIR}/include/${target}.h)
  set(abs_files)
  foreach(f IN LISTS ARGN)
    list(APPEND abs_files ${CMAKE_CURRENT_SOURCE_DIR}/${f})
  endforeach()
  string(REPLACE ";" "," files_arg "${ARGN}")
  add_custom_command(
    OUTPUT ${out_cpp} ${out_h}
    COMMAND ${CMAKE_COMMAND} -DOUT_CPP=${out_cpp} -DOUT_H=${out_h}
            -DNAMESPACE=${namespace} -DHEADER_NAME=${target}.h
            -DBASE_DIR=${CMAKE_CURRENT_SOURCE_DIR} "-DFILES=${files_arg}"
            -P ${TOOND_EMBED_SCRIPT}
    DEPENDS ${abs_files} ${TOOND_EMBED_SCRIPT}
    COMMENT "Embedding ${target}")
  add_library(${target} STATIC ${out_cpp} ${out_h})
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/include)
  target_link_libraries(${target} PRIVATE toond_warnings)
endfunction()
