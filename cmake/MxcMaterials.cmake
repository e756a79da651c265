# mxc_add_materials: MaterialX documents compiled to shaders by a build rule per document.
#
#   find_package(mxc REQUIRED)
#   mxc_add_materials(<target> [ALL]
#                     DOCUMENTS <file.mtlx>...
#                     [OUTPUT_DIRECTORY <dir>]      # default: ${CMAKE_CURRENT_BINARY_DIR}/<target>
#                     [LANGUAGE spirv|glsl|essl|msl|hlsl|wgsl]   # default: spirv
#                     [OPTIONS <mxc compile options>...])        # --set, --param, --library, -O, ...
#
# Each document <name>.mtlx becomes <dir>/<name>.<ext> (with _<material> for a document of several
# materials), its interface <name>.json and vertex stage <name>.vert.<ext>: the files
# `mxc compile --list-outputs` names, asked at configure time, so that Ninja knows every output.
# The rule's depfile (`mxc compile --depfile`) lists the document's includes, the library files
# and the image files it reads, so that a change to any of them recompiles that document alone;
# a change to the document itself also re-runs the configuration (it may add a material). The
# albedo tables the shaders sample are one rule of their own: <dir>/mxc_albedo_tables.bin.
# <target> depends on every output; the variable <target>_OUTPUTS lists them.

function(mxc_add_materials target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "ALL" "OUTPUT_DIRECTORY;LANGUAGE" "DOCUMENTS;OPTIONS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "mxc_add_materials(${target}): unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_DOCUMENTS)
    message(FATAL_ERROR "mxc_add_materials(${target}): no DOCUMENTS")
  endif()
  if(NOT ARG_OUTPUT_DIRECTORY)
    set(ARG_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  endif()
  get_filename_component(dir "${ARG_OUTPUT_DIRECTORY}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  if(NOT ARG_LANGUAGE)
    set(ARG_LANGUAGE spirv)
  endif()
  set(extensions spirv .spv glsl .glsl essl .essl msl .metal hlsl .hlsl wgsl .wgsl)
  list(FIND extensions "${ARG_LANGUAGE}" at)
  if(at EQUAL -1 OR at GREATER 10)
    message(FATAL_ERROR "mxc_add_materials(${target}): LANGUAGE ${ARG_LANGUAGE} is not one of spirv, glsl, essl, msl, hlsl, wgsl")
  endif()
  math(EXPR at "${at} + 1")
  list(GET extensions ${at} extension)
  # The program, to ask for the outputs now; the rules run it through the imported target.
  get_target_property(mxc_program mxc::mxc LOCATION)
  file(MAKE_DIRECTORY "${dir}")

  set(outputs "")
  set(tables "${dir}/mxc_albedo_tables.bin")
  add_custom_command(OUTPUT "${tables}"
                     COMMAND mxc::mxc compile -q --tables "${dir}"
                     DEPENDS mxc::mxc
                     COMMENT "mxc: albedo tables for ${target}"
                     VERBATIM)
  list(APPEND outputs "${tables}")
  foreach(document IN LISTS ARG_DOCUMENTS)
    get_filename_component(source "${document}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${source}" NAME_WE)
    set(shader "${dir}/${name}${extension}")
    set(depfile "${dir}/${name}.d")
    set(arguments compile "${source}" -o "${shader}" --target ${ARG_LANGUAGE} ${ARG_OPTIONS})
    execute_process(COMMAND "${mxc_program}" ${arguments} --list-outputs
                    OUTPUT_VARIABLE listed ERROR_VARIABLE problem RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "mxc_add_materials(${target}): ${document} cannot be compiled:\n${problem}")
    endif()
    string(REGEX REPLACE "\n$" "" listed "${listed}")
    string(REPLACE "\n" ";" written "${listed}")
    # A new material in the document means new outputs: the configuration runs again.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")
    add_custom_command(OUTPUT ${written}
                       COMMAND mxc::mxc ${arguments} -q --depfile "${depfile}"
                       DEPENDS "${source}" mxc::mxc
                       DEPFILE "${depfile}"
                       COMMENT "mxc: ${document}"
                       VERBATIM)
    list(APPEND outputs ${written})
  endforeach()
  if(ARG_ALL)
    add_custom_target(${target} ALL DEPENDS ${outputs})
  else()
    add_custom_target(${target} DEPENDS ${outputs})
  endif()
  set(${target}_OUTPUTS "${outputs}" PARENT_SCOPE)
endfunction()
