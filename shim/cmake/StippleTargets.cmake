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

function(stipple_add_benchmark source)
  get_filename_component(stem ${source} NAME_WE)
  set(target shim_${stem})
  add_executable(${target} ${source})
  _stipple_link_choice(${source} ${target})
  target_link_libraries(${target} PRIVATE benchmark::benchmark stipple_version stipple_analysis)
endfunction()
