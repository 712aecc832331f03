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
# A sanitizer build's library cannot be dlopened by an uninstrumented python3.
if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  find_program(STIPPLE_PYTHON3 python3)
  if(STIPPLE_PYTHON3)
    stipple_add_test(PART shim NAME quarter_disk_py LABELS statistical
      COMMAND ${STIPPLE_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/examples/quarter_disk.py $<TARGET_FILE:stipple>)
  endif()
endif()

# 1.0 compatibility: abidiff against the 1.0 baseline (kept in abi/1.0/) reports additions only, and the C example
# host built against the 1.0 header (abi/1.0/stipple/stipple.h, the released header unmodified) runs against this
# library through dlopen.
if(STIPPLE_ABIDIFF)
  stipple_add_test(PART shim NAME abi_since_1_0 LABELS unit
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/abi/check-abi.sh $<TARGET_FILE:stipple>
            shim/abi/1.0/libstipple.abi)
endif()
add_executable(quarter_disk_abi_1_0 examples/quarter_disk.c)
set_target_properties(quarter_disk_abi_1_0 PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(quarter_disk_abi_1_0 PRIVATE -pedantic -Wall -Wextra -Werror)
target_include_directories(quarter_disk_abi_1_0 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/abi/1.0)
target_link_libraries(quarter_disk_abi_1_0 PRIVATE ${CMAKE_DL_LIBS} m)
add_dependencies(quarter_disk_abi_1_0 stipple)
stipple_add_test(PART shim NAME host_abi_1_0 LABELS statistical
  COMMAND quarter_disk_abi_1_0 $<TARGET_FILE:stipple>)

# The stipple.hpp host: unbiased against the closed form with indices past N, progressive passes equal one pass,
# stratified per call index with data-dependent skipped calls (see the source).
stipple_add_test(PART shim NAME tiny_path_tracer LABELS statistical COMMAND tiny_path_tracer)

# The importable NumPy binding (examples/python/stipple_numpy.py) and its test; needs Debian's python3-numpy
# (hence /usr/bin first), and no sanitizer build (an uninstrumented python3 cannot load it).
if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  find_program(STIPPLE_NUMPY_PYTHON3 NAMES python3 HINTS /usr/bin)
  if(STIPPLE_NUMPY_PYTHON3)
    execute_process(COMMAND ${STIPPLE_NUMPY_PYTHON3} -c "import numpy" RESULT_VARIABLE _stipple_no_numpy
                    OUTPUT_QUIET ERROR_QUIET)
    if(_stipple_no_numpy EQUAL 0)
      stipple_add_test(PART shim NAME stipple_numpy LABELS unit statistical
        COMMAND ${STIPPLE_NUMPY_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/examples/python/test_stipple_numpy.py
                $<TARGET_FILE:stipple>)
    else()
      message(WARNING "python3 without numpy (python3-numpy): the shim.stipple_numpy test is not registered")
    endif()
  endif()
endif()
