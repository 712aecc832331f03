# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# StippleTargets.cmake — one executable per benchmark source file, configured by a comment in the file:
#   // stipple-link: shared             link libstipple.so (the C ABI as hosts see it) instead of the internal
#                                       objects (which give access to the C++ internals, e.g. stipple::pointsets).
# Executables land in <build>/bin.

function(_stipple_link_choice source target)
  file(READ ${source} text)
  if(text MATCHES "//[ ]*stipple-link:[ ]*shared")
    target_link_libraries(${target} PRIVATE stipple)
  else()
    target_link_libraries(${target} PRIVATE stipple_objects)
  endif()
  set(_stipple_text "${text}" PARENT_SCOPE)
endfunction()

# A program of bench/ that is not a Google Benchmark (e.g. the study's Figure 3): defined without the benchmarks,
# but built by default only with them or the tests (ci/main.sh names the Figure 3 program it needs).
function(stipple_add_bench_program source)
  get_filename_component(stem ${source} NAME_WE)
  set(target shim_${stem})
  if(STIPPLE_BUILD_BENCHMARKS OR STIPPLE_BUILD_TESTS)
    add_executable(${target} ${source})
  else()
    add_executable(${target} EXCLUDE_FROM_ALL ${source})
  endif()
  _stipple_link_choice(${source} ${target})
  target_link_libraries(${target} PRIVATE stipple_version stipple_analysis)
endfunction()

function(stipple_add_benchmark source)
  stipple_add_bench_program(${source})
  get_filename_component(stem ${source} NAME_WE)
  target_link_libraries(shim_${stem} PRIVATE benchmark::benchmark)
endfunction()
