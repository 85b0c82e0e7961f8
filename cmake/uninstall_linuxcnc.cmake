# cmake -DFILES="<dir>/firtp.so;<dir>/firtp_tp.so" -P uninstall_linuxcnc.cmake
# The way back from `install-linuxcnc`: removes the modules it copied into LinuxCNC's module
# directory. A file a Debian package owns (the firtp package) is left to dpkg -r.
find_program(DPKG_QUERY dpkg-query)
foreach(file IN LISTS FILES)
  if(NOT EXISTS "${file}")
    message(STATUS "uninstall-linuxcnc: ${file}: not there")
    continue()
  endif()
  if(DPKG_QUERY)
    execute_process(COMMAND ${DPKG_QUERY} -S "${file}" RESULT_VARIABLE unowned OUTPUT_VARIABLE owner ERROR_QUIET
      OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(unowned EQUAL 0)
      string(REGEX REPLACE ":.*" "" owner "${owner}")
      message(STATUS "uninstall-linuxcnc: ${file} belongs to the package ${owner}: left to dpkg -r ${owner}")
      continue()
    endif()
  endif()
  file(REMOVE "${file}")
  if(EXISTS "${file}")
    message(FATAL_ERROR "uninstall-linuxcnc: cannot remove ${file} (root?)")
  endif()
  message(STATUS "uninstall-linuxcnc: removed ${file}")
endforeach()
