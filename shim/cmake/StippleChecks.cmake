# StippleChecks.cmake — CTest checks of the library as a product: exported surface, ABI, header, example hosts.

# The header compiles as strict C99 and as strict C++ (a compile-only test; it also builds as a target below).
add_test(NAME shim.header_c99
  COMMAND ${CMAKE_C_COMPILER} -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_c99.c)
add_test(NAME shim.header_cxx
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -x c++ -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_c99.c)
add_test(NAME shim.header_hpp
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++17 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
# stipple.hpp as C++11 (the oldest standard it supports) and without exceptions, strict.
add_test(NAME shim.header_hpp_cxx11
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++11 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
add_test(NAME shim.header_hpp_no_exceptions
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++11 -fno-exceptions -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
set_tests_properties(shim.header_c99 shim.header_cxx shim.header_hpp shim.header_hpp_cxx11
                     shim.header_hpp_no_exceptions PROPERTIES LABELS unit)
add_library(stipple_header_c99 OBJECT tests/header_c99.c)
set_target_properties(stipple_header_c99 PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(stipple_header_c99 PRIVATE -pedantic -Wall -Wextra -Werror)
target_link_libraries(stipple_header_c99 PRIVATE stipple_headers)

# Only stipple_* exported, SONAME libstipple.so.1.
add_test(NAME shim.exports
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-exports.sh $<TARGET_FILE:stipple>
          ${CMAKE_CURRENT_SOURCE_DIR}/include/stipple/stipple.h)
set_tests_properties(shim.exports PROPERTIES LABELS unit)

# cmake --install of the stipple component, then find_package and pkg-config consumers build and run against it.
# Not under sanitizers: the consumer is built without them.
if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  add_test(NAME shim.install
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-install.sh ${CMAKE_BINARY_DIR}
            ${CMAKE_CURRENT_SOURCE_DIR}/tests/install_consumer ${CMAKE_C_COMPILER})
  set_tests_properties(shim.install PROPERTIES LABELS unit)
endif()

# abidiff against the committed baseline; fails on an incompatible change.
find_program(STIPPLE_ABIDIFF abidiff)
if(STIPPLE_ABIDIFF)
  add_test(NAME shim.abi COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>)
  set_tests_properties(shim.abi PROPERTIES LABELS unit)
else()
  message(WARNING "abidiff (abigail-tools) not found: the shim.abi test is not registered")
endif()

# The example hosts: each prints its error table and asserts stratified < independent (see the sources).
add_test(NAME shim.quarter_disk_c COMMAND quarter_disk)
set_tests_properties(shim.quarter_disk_c PROPERTIES LABELS "statistical")
# The Python host (examples/quarter_disk.py) is registered with the Python package (python/CMakeLists.txt).

# Compatibility with every released minor version: abidiff against its baseline (kept in abi/1.<m>/) reports
# additions only, and the C example host built against its header (abi/1.<m>/stipple/stipple.h, the released header
# unmodified) runs against this library through dlopen.
foreach(_minor 0 1)
  if(STIPPLE_ABIDIFF)
    add_test(NAME shim.abi_since_1_${_minor}
      COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>
              shim/abi/1.${_minor}/libstipple.abi)
    set_tests_properties(shim.abi_since_1_${_minor} PROPERTIES LABELS unit)
  endif()
  add_executable(quarter_disk_abi_1_${_minor} examples/quarter_disk.c)
  set_target_properties(quarter_disk_abi_1_${_minor} PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  target_compile_options(quarter_disk_abi_1_${_minor} PRIVATE -pedantic -Wall -Wextra -Werror)
  target_include_directories(quarter_disk_abi_1_${_minor} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/abi/1.${_minor})
  target_link_libraries(quarter_disk_abi_1_${_minor} PRIVATE ${CMAKE_DL_LIBS} m)
  add_dependencies(quarter_disk_abi_1_${_minor} stipple)
  add_test(NAME shim.host_abi_1_${_minor} COMMAND quarter_disk_abi_1_${_minor} $<TARGET_FILE:stipple>)
  set_tests_properties(shim.host_abi_1_${_minor} PROPERTIES LABELS "statistical")
endforeach()

# The stipple.hpp host: unbiased against the closed form with indices past N, progressive passes equal one pass,
# stratified per call index with data-dependent skipped calls (see the source).
add_test(NAME shim.tiny_path_tracer COMMAND tiny_path_tracer)
set_tests_properties(shim.tiny_path_tracer PROPERTIES LABELS "statistical")

# The C++11 host built with -fno-exceptions (examples/analytic_host.cpp): arrays unbiased against the closed form,
# stratified across the N * k values, the cursor's batches equal the per-sample calls, errors through status forms.
add_test(NAME shim.analytic_host COMMAND analytic_host --check)
set_tests_properties(shim.analytic_host PROPERTIES LABELS "statistical")
