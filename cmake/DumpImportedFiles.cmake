# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Injected by ci/check_package_sets.py through CMAKE_PROJECT_INCLUDE: after every find_package, appends to
# STIPPLE_IMPORTED_FILES_OUT the package's config file and each absolute file that the imported targets of the
# calling directory name (their libraries, executables such as OpenImageIO's tools, include folders), as
# "target<TAB>path" lines. Those files
# come from the packages found; a package set that installs a config but not what it names fails configure on a
# fresh machine. (Imported targets are visible only in the directory that found them, hence the wrapper.)

function(_stipple_dump_imported_targets package)
  get_property(targets DIRECTORY PROPERTY IMPORTED_TARGETS)
  set(lines "")
  if(${package}_CONFIG AND IS_ABSOLUTE "${${package}_CONFIG}") # the package's config file itself
    string(APPEND lines "find_package(${package})\t${${package}_CONFIG}\n")
  endif()
  foreach(target IN LISTS targets)
    set(properties IMPORTED_LOCATION INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
                   INTERFACE_LINK_LIBRARIES)
    get_target_property(configurations ${target} IMPORTED_CONFIGURATIONS)
    if(configurations)
      foreach(configuration IN LISTS configurations)
        string(TOUPPER "${configuration}" configuration)
        list(APPEND properties IMPORTED_LOCATION_${configuration})
      endforeach()
    endif()
    foreach(property IN LISTS properties)
      get_target_property(values ${target} ${property})
      if(NOT values)
        continue()
      endif()
      foreach(value IN LISTS values)
        if(IS_ABSOLUTE "${value}")
          string(APPEND lines "${target}\t${value}\n")
        endif()
      endforeach()
    endforeach()
  endforeach()
  file(APPEND "${STIPPLE_IMPORTED_FILES_OUT}" "${lines}")
endfunction()

if(STIPPLE_IMPORTED_FILES_OUT AND NOT COMMAND _stipple_find_package_wrapped)
  function(_stipple_find_package_wrapped)
  endfunction()
  file(WRITE "${STIPPLE_IMPORTED_FILES_OUT}" "")
  macro(find_package)
    _find_package(${ARGV})
    _stipple_dump_imported_targets("${ARGV0}")
  endmacro()
endif()
