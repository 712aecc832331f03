# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Runs stipple-render on the Cornell box (small, few samples) and checks outputs and printed report.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${EXE} ${SCENE} --pattern stratified --spp 4 --seed 1 --width 32 --height 32 --threads 2
                        -o ${OUT}/out.exr
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stipple-render failed (${rc}):\n${out}\n${err}")
endif()
foreach(f out.exr out.png)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "${f} was not written:\n${out}")
  endif()
endforeach()
foreach(expected "0 pixel 2D x1" "b0.light.pos 2D" "BVH build" "render [0-9.]+ s" "sampler [0-9.]+ s" "Mrays/s"
                 "non-finite samples 0")
  if(NOT out MATCHES "${expected}")
    message(FATAL_ERROR "output lacks '${expected}':\n${out}")
  endif()
endforeach()
file(GLOB leftovers ${OUT}/*.tmp*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
execute_process(COMMAND ${EXE} ${SCENE} --print-layout OUTPUT_VARIABLE layout RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT layout MATCHES "^0 pixel 2D x1\n1 b0.light.pos")
  message(FATAL_ERROR "--print-layout: rc ${rc}, output:\n${layout}")
endif()
execute_process(COMMAND ${EXE} --version OUTPUT_VARIABLE version RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT version MATCHES "^stipple-render [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "--version: rc ${rc}, output:\n${version}")
endif()
