# StippleTargets.cmake — one executable per test / benchmark source file, configured by comments in the file.
#
# Conventions read from a source file's text:
#   // ctest-labels: unit;statistical   CTest labels (default: unit). Known: unit statistical render slow parallel.
#   // stipple-link: shared             link libstipple.so (the C ABI as hosts see it) instead of the internal
#                                       objects (which give access to the C++ internals, e.g. stipple::pointsets).
#   #include <boost/test/included/...>  the header-only Boost.Test variant: the Boost library is not linked.
# Test names are shim.<file stem>; executables land in <build>/bin.

function(_stipple_link_choice source target)
  file(READ ${source} text)
  if(text MATCHES "//[ ]*stipple-link:[ ]*shared")
    target_link_libraries(${target} PRIVATE stipple)
  else()
    target_link_libraries(${target} PRIVATE stipple_objects)
  endif()
  set(_stipple_text "${text}" PARENT_SCOPE)
endfunction()

function(stipple_add_boost_test source)
  get_filename_component(stem ${source} NAME_WE)
  set(target shim_${stem})
  add_executable(${target} ${source})
  _stipple_link_choice(${source} ${target})
  if(NOT _stipple_text MATCHES "boost/test/included/")
    target_link_libraries(${target} PRIVATE Boost::unit_test_framework)
  endif()
  set(labels unit)
  if(_stipple_text MATCHES "//[ ]*ctest-labels:[ ]*([A-Za-z0-9_; ]+)")
    string(REPLACE " " "" labels "${CMAKE_MATCH_1}")
  endif()
  add_test(NAME shim.${stem} COMMAND ${target} --color_output=no --report_level=short)
  set_tests_properties(shim.${stem} PROPERTIES LABELS "${labels}")
endfunction()

function(stipple_add_benchmark source)
  get_filename_component(stem ${source} NAME_WE)
  set(target shim_${stem})
  add_executable(${target} ${source})
  _stipple_link_choice(${source} ${target})
  target_link_libraries(${target} PRIVATE benchmark::benchmark)
endfunction()
