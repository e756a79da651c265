# mxc_embed_files(<target> SYMBOL <function> BASE_DIR <dir> FILES <files...>)
#
# Builds a static library <target> that holds the given data files (node definitions, GLSL library code)
# inside the binary, so `mxc` runs without an install step. The library defines
#   std::span<const mxc::EmbeddedFile> <function>();
# (declared by the caller) whose entries carry the path relative to BASE_DIR and the bytes.
# The files stay real files in the source tree; the generated .cpp is rebuilt when any of them changes.
function(mxc_embed_files target)
  cmake_parse_arguments(ARG "" "SYMBOL;BASE_DIR" "FILES" ${ARGN})
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp")
  set(list_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_files.txt")
  string(REPLACE ";" "\n" file_lines "${ARG_FILES}")
  file(WRITE "${list_file}.tmp" "${file_lines}")
  file(COPY_FILE "${list_file}.tmp" "${list_file}" ONLY_IF_DIFFERENT)
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DLIST=${list_file} -DBASE_DIR=${ARG_BASE_DIR} -DSYMBOL=${ARG_SYMBOL}
            -P "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    DEPENDS ${ARG_FILES} "${list_file}" "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    COMMENT "Embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC "${out}")
  target_include_directories(${target} PUBLIC "${PROJECT_SOURCE_DIR}")
endfunction()
