# SPDX-License-Identifier: MIT
# Sanitizer and fuzzing instrumentation for the whole build (every target, core included).
if(LAYERMOD_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

if(LAYERMOD_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "LAYERMOD_BUILD_FUZZERS needs clang (libFuzzer); configure with CXX=clang++")
  endif()
  # Coverage instrumentation everywhere; only the fuzz executables link libFuzzer's main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
