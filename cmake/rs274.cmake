# LinuxCNC 2.9's G-code interpreter, which firtp's reader (component/program) drives: librs274 and
# libtooldata (package linuxcnc-uspace) with the headers canon.hh, interp_base.hh, emctool.h
# (package linuxcnc-uspace-dev); both are in .ci/deps. Required: without them firtp cannot read
# G-code, and configuring stops saying what to install.
#
# Result: imported target firtp::rs274 (headers as system headers, the libraries librs274 needs).
#   FIRTP_RS274_INCLUDE_DIR   where canon.hh is (default: FIRTP_LINUXCNC_INCLUDE_DIR or /usr/include/linuxcnc)
#   FIRTP_RS274_EXECUTABLE    LinuxCNC's standalone `rs274` (tests compare with `rs274 -g`), when found
include_guard(GLOBAL)

if(NOT DEFINED FIRTP_LINUXCNC_INCLUDE_DIR)
  set(FIRTP_LINUXCNC_INCLUDE_DIR /usr/include/linuxcnc)
endif()
find_path(FIRTP_RS274_INCLUDE_DIR canon.hh interp_base.hh emctool.h
  HINTS ${FIRTP_LINUXCNC_INCLUDE_DIR} PATH_SUFFIXES linuxcnc NO_CACHE)
find_library(FIRTP_RS274_LIBRARY rs274 NO_CACHE)
find_library(FIRTP_TOOLDATA_LIBRARY tooldata NO_CACHE)
foreach(_v FIRTP_RS274_INCLUDE_DIR FIRTP_RS274_LIBRARY FIRTP_TOOLDATA_LIBRARY)
  if(NOT ${_v})
    message(FATAL_ERROR "firtp reads G-code with LinuxCNC 2.9's interpreter, but ${_v} was not found: "
      "install the Debian packages linuxcnc-uspace and linuxcnc-uspace-dev (bash .ci/deps does), "
      "or set FIRTP_LINUXCNC_INCLUDE_DIR / CMAKE_PREFIX_PATH to a LinuxCNC 2.9 installation")
  endif()
endforeach()
find_program(FIRTP_RS274_EXECUTABLE rs274 PATHS /usr/bin)

add_library(firtp::rs274 INTERFACE IMPORTED)
target_include_directories(firtp::rs274 SYSTEM INTERFACE ${FIRTP_RS274_INCLUDE_DIR})
target_link_libraries(firtp::rs274 INTERFACE ${FIRTP_RS274_LIBRARY} ${FIRTP_TOOLDATA_LIBRARY})
message(STATUS "firtp: LinuxCNC's interpreter ${FIRTP_RS274_LIBRARY} (headers ${FIRTP_RS274_INCLUDE_DIR}, rs274 ${FIRTP_RS274_EXECUTABLE})")
