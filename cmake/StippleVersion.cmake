# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The target stipple_version: <build>/generated/stipple/version.h with the project version and, in a git
# checkout, the git description. Every part's --version and identity strings come from it.
find_package(Git QUIET)
set(STIPPLE_GIT_DESCRIPTION "")
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} OUTPUT_VARIABLE STIPPLE_GIT_DESCRIPTION
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _git_result)
  if(NOT _git_result EQUAL 0)
    set(STIPPLE_GIT_DESCRIPTION "")
  endif()
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.h.in ${PROJECT_BINARY_DIR}/generated/stipple/version.h @ONLY)
add_library(stipple_version INTERFACE)
target_include_directories(stipple_version INTERFACE $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>)
