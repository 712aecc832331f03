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
set_tests_properties(shim.header_c99 shim.header_cxx shim.header_hpp PROPERTIES LABELS unit)
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

# 1.0 compatibility: abidiff against the 1.0 baseline (kept in abi/1.0/) reports additions only, and the C example
# host built against the 1.0 header (abi/1.0/stipple/stipple.h, the released header unmodified) runs against this
# library through dlopen.
if(STIPPLE_ABIDIFF)
  add_test(NAME shim.abi_since_1_0 COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>
                                           shim/abi/1.0/libstipple.abi)
  set_tests_properties(shim.abi_since_1_0 PROPERTIES LABELS unit)
endif()
add_executable(quarter_disk_abi_1_0 examples/quarter_disk.c)
set_target_properties(quarter_disk_abi_1_0 PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(quarter_disk_abi_1_0 PRIVATE -pedantic -Wall -Wextra -Werror)
target_include_directories(quarter_disk_abi_1_0 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/abi/1.0)
target_link_libraries(quarter_disk_abi_1_0 PRIVATE ${CMAKE_DL_LIBS} m)
add_dependencies(quarter_disk_abi_1_0 stipple)
add_test(NAME shim.host_abi_1_0 COMMAND quarter_disk_abi_1_0 $<TARGET_FILE:stipple>)
set_tests_properties(shim.host_abi_1_0 PROPERTIES LABELS "statistical")

# The stipple.hpp host: unbiased against the closed form with indices past N, progressive passes equal one pass,
# stratified per call index with data-dependent skipped calls (see the source).
add_test(NAME shim.tiny_path_tracer COMMAND tiny_path_tracer)
set_tests_properties(shim.tiny_path_tracer PROPERTIES LABELS "statistical")
