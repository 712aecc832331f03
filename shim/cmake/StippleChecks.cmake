# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# StippleChecks.cmake — CTest checks of the library as a product: exported surface, ABI, header, example hosts.

# The header compiles as strict C99 and as strict C++ (a compile-only test; it also builds as a target below).
stipple_add_test(PART shim NAME header_c99 LABELS unit
  COMMAND ${CMAKE_C_COMPILER} -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_c99.c)
stipple_add_test(PART shim NAME header_cxx LABELS unit
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -x c++ -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_c99.c)
stipple_add_test(PART shim NAME header_hpp LABELS unit
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++17 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
# stipple.hpp as C++11 (the oldest standard it supports) and without exceptions, strict.
stipple_add_test(PART shim NAME header_hpp_cxx11 LABELS unit
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++11 -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
stipple_add_test(PART shim NAME header_hpp_no_exceptions LABELS unit
  COMMAND ${CMAKE_CXX_COMPILER} -std=c++11 -fno-exceptions -pedantic -Wall -Wextra -Werror -fsyntax-only
          -I${CMAKE_CURRENT_SOURCE_DIR}/include ${CMAKE_CURRENT_SOURCE_DIR}/tests/header_hpp.cpp)
add_library(stipple_header_c99 OBJECT tests/header_c99.c)
set_target_properties(stipple_header_c99 PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(stipple_header_c99 PRIVATE -pedantic -Wall -Wextra -Werror)
target_link_libraries(stipple_header_c99 PRIVATE stipple_headers)

# Only stipple_* exported, SONAME libstipple.so.1.
stipple_add_test(PART shim NAME exports LABELS unit
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-exports.sh $<TARGET_FILE:stipple>
          ${CMAKE_CURRENT_SOURCE_DIR}/include/stipple/stipple.h)

# cmake --install of the stipple component, then find_package and pkg-config consumers build and run against it.
# Not under sanitizers: the consumer is built without them.
if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  stipple_add_test(PART shim NAME install LABELS unit
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-install.sh ${CMAKE_BINARY_DIR}
            ${CMAKE_CURRENT_SOURCE_DIR}/tests/install_consumer ${CMAKE_C_COMPILER})
endif()

# abidiff against the committed baseline; fails on an incompatible change.
find_program(STIPPLE_ABIDIFF abidiff)
if(STIPPLE_ABIDIFF)
  stipple_add_test(PART shim NAME abi LABELS unit
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>)
else()
  message(WARNING "abidiff (abigail-tools) not found: the shim.abi test is not registered")
endif()

# The example hosts: each prints its error table and asserts stratified < independent (see the sources).
stipple_add_test(PART shim NAME quarter_disk_c LABELS statistical COMMAND quarter_disk)
# The Python host (examples/quarter_disk.py) is registered with the Python package (python/CMakeLists.txt).

# Compatibility with every released minor version: abidiff against its baseline (kept in abi/1.<m>/) reports
# additions only, and the C example host built against its header (abi/1.<m>/stipple/stipple.h, the released header
# unmodified) runs against this library through dlopen.
foreach(_minor 0 1)
  if(STIPPLE_ABIDIFF)
    stipple_add_test(PART shim NAME abi_since_1_${_minor} LABELS unit
      COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>
              shim/abi/1.${_minor}/libstipple.abi)
  endif()
  add_executable(quarter_disk_abi_1_${_minor} examples/quarter_disk.c)
  set_target_properties(quarter_disk_abi_1_${_minor} PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  target_compile_options(quarter_disk_abi_1_${_minor} PRIVATE -pedantic -Wall -Wextra -Werror)
  target_include_directories(quarter_disk_abi_1_${_minor} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/abi/1.${_minor})
  target_link_libraries(quarter_disk_abi_1_${_minor} PRIVATE ${CMAKE_DL_LIBS} m)
  add_dependencies(quarter_disk_abi_1_${_minor} stipple)
  stipple_add_test(PART shim NAME host_abi_1_${_minor} LABELS statistical
    COMMAND quarter_disk_abi_1_${_minor} $<TARGET_FILE:stipple>)
endforeach()

# The stipple.hpp host: unbiased against the closed form with indices past N, progressive passes equal one pass,
# stratified per call index with data-dependent skipped calls (see the source).
stipple_add_test(PART shim NAME tiny_path_tracer LABELS statistical COMMAND tiny_path_tracer)

# The C++11 host built with -fno-exceptions (examples/analytic_host.cpp): arrays unbiased against the closed form,
# stratified across the N * k values, the cursor's batches equal the per-sample calls, errors through status forms.
stipple_add_test(PART shim NAME analytic_host LABELS statistical COMMAND analytic_host --check)
