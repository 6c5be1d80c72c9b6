# SPDX-License-Identifier: MIT
# Warning flags shared by every LayerMOD target.
function(layermod_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wno-deprecated-enum-enum-conversion)
  if(LAYERMOD_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(LAYERMOD_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()

# layermod_add_stage(NAME SOURCES ... DEPS ...): one core stage library, linking only downward.
function(layermod_add_stage name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(layermod_${name} STATIC ${ARG_SOURCES})
  target_include_directories(layermod_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/core>
    $<INSTALL_INTERFACE:include/layermod>)
  target_link_libraries(layermod_${name} PUBLIC ${ARG_DEPS})
  layermod_set_warnings(layermod_${name})
endfunction()
