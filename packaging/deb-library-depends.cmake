# Included by cpack (the DEB generator's project file, written by packaging/CMakeLists.txt):
# computes the library package's Depends with dpkg-shlibdeps, as CPack does for the other packages.
# CPack's own run would also write postinst/postrm scripts calling ldconfig (for any shared object
# in /usr/lib), which Debian's policy replaces by the `triggers` file the package ships instead.
function(toyhost_library_depends library scratch out_var)
  find_program(TOYHOST_DPKG_SHLIBDEPS dpkg-shlibdeps REQUIRED)
  # dpkg-shlibdeps reads debian/control from its working folder; an empty one will do.
  file(REMOVE_RECURSE "${scratch}")
  file(WRITE "${scratch}/debian/control" "")
  execute_process(COMMAND ${TOYHOST_DPKG_SHLIBDEPS} -O "${library}"
    WORKING_DIRECTORY "${scratch}"
    OUTPUT_VARIABLE output ERROR_VARIABLE error RESULT_VARIABLE result
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT result EQUAL 0 OR NOT output MATCHES "shlibs:Depends=([^\n]+)")
    message(FATAL_ERROR "dpkg-shlibdeps ${library} failed (${result}): ${error}${output}")
  endif()
  set(${out_var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()
