# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# 1. `ldd stipple-render` must not list libstipple (it is dlopened).
# 2. No source in integrators/ may use another random source than the shim.
execute_process(COMMAND ldd ${EXE} OUTPUT_VARIABLE deps RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ldd ${EXE} failed (${rc})")
endif()
if(deps MATCHES "libstipple")
  message(FATAL_ERROR "stipple-render links libstipple; it must dlopen it:\n${deps}")
endif()
file(GLOB_RECURSE sources ${ROOT}/*.cpp ${ROOT}/*.h ${ROOT}/*.hpp)
# The patterns are assembled so that this file does not match itself.
set(rnd "rand")
set(patterns "<${rnd}om>" "[^a-z_]${rnd}\\(" "s${rnd}\\(" "${rnd}om_device" "mt19937" "d${rnd}48" "minstd_${rnd}"
             "default_${rnd}om_engine" "${rnd}_r\\(" "arc4${rnd}om")
set(bad "")
foreach(f IN LISTS sources)
  file(STRINGS ${f} lines)
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    foreach(p IN LISTS patterns)
      if(line MATCHES "${p}")
        string(APPEND bad "${f}:${n}: ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "random sources other than libstipple found:\n${bad}")
endif()
list(LENGTH sources count)
message(STATUS "checked ${count} files: no other random source; stipple-render does not link libstipple")
