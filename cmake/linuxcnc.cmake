# LinuxCNC 2.9 (uspace) modules built from firtp's sources, next to the hal-shim ones.
#
# Options and results:
#   FIRTP_LINUXCNC              AUTO (default) | ON | OFF. AUTO: on when hal.h and rtapi.h are in
#                               FIRTP_LINUXCNC_INCLUDE_DIR (package linuxcnc-uspace-dev).
#   FIRTP_LINUXCNC_INCLUDE_DIR  LinuxCNC's headers (/usr/include/linuxcnc).
#   FIRTP_LINUXCNC_MODULE_DIR   where `install-linuxcnc` copies the modules: RTLIBDIR of
#                               /usr/share/linuxcnc/Makefile.modinc (rtapi_app dlopens
#                               <dir>/<name>.so and has no search path), else /usr/lib/linuxcnc/modules.
#   FIRTP_LINUXCNC_ENABLED      (result) TRUE when modules are built.
#   FIRTP_LINUXCNC_OUTPUT_DIR   ${CMAKE_BINARY_DIR}/linuxcnc: every module's .so goes there, apart
#                               from the hal-shim builds of the same names in ${CMAKE_BINARY_DIR}/lib.
#
# firtp_linuxcnc_add_module(<name> SOURCES <file>... [LIBS <lib>...] [INCLUDES <dir>...]
#                           [EXPORTS <symbol>...])
#   Builds target linuxcnc_<name> -> ${FIRTP_LINUXCNC_OUTPUT_DIR}/<name>.so, loadable with
#   `halcmd loadrt <name>` once installed. SOURCES are compiled as Makefile.modinc compiles a module
#   (-DUSPACE -DRTAPI -D_GNU_SOURCE -Drealtime -D__MODULE__ -DSIM -fPIC -fno-fast-math ...) against
#   LinuxCNC's headers (never hal-shim's: do not put targets that carry hal-shim's include
#   directory, such as firtp_hal_component or firtp_component_logic, in LIBS). LIBS (static
#   libraries such as firtp_core, built -fPIC) are linked into the module. The module is linked
#   -shared -Bsymbolic with a version script that exports only rtapi_app_main, rtapi_app_exit,
#   rtapi_info_* (module information and parameters, read by rtapi_app with dlsym) and EXPORTS
#   (e.g. the tp* functions a planner module provides to motmod): rtapi_app opens every module
#   RTLD_GLOBAL, so everything else, the C++ core included, stays local to the module.
#   The module is added to the target `install-linuxcnc` (which, without LinuxCNC, fails saying why)
#   and to `uninstall-linuxcnc`, which removes it again unless a package (dpkg) owns the file. The
#   Debian package (cmake/packaging.cmake) is the installed way; these two are for development.
#   Call it only when FIRTP_LINUXCNC_ENABLED.
include_guard(GLOBAL)
include(CheckCXXCompilerFlag)

set(FIRTP_LINUXCNC AUTO CACHE STRING "Build the LinuxCNC modules: AUTO (when LinuxCNC's headers are found), ON, OFF")
set_property(CACHE FIRTP_LINUXCNC PROPERTY STRINGS AUTO ON OFF)
set(FIRTP_LINUXCNC_INCLUDE_DIR /usr/include/linuxcnc CACHE PATH "LinuxCNC's headers (hal.h, rtapi.h)")

set(FIRTP_LINUXCNC_ENABLED FALSE)
if(EXISTS ${FIRTP_LINUXCNC_INCLUDE_DIR}/hal.h AND EXISTS ${FIRTP_LINUXCNC_INCLUDE_DIR}/rtapi.h)
  if(NOT FIRTP_LINUXCNC STREQUAL "OFF")
    set(FIRTP_LINUXCNC_ENABLED TRUE)
  endif()
elseif(FIRTP_LINUXCNC STREQUAL "ON")
  message(FATAL_ERROR "FIRTP_LINUXCNC=ON but ${FIRTP_LINUXCNC_INCLUDE_DIR} has no hal.h and rtapi.h "
    "(install linuxcnc-uspace-dev or set FIRTP_LINUXCNC_INCLUDE_DIR)")
endif()
if(NOT FIRTP_LINUXCNC MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "FIRTP_LINUXCNC must be AUTO, ON or OFF, not '${FIRTP_LINUXCNC}'")
endif()

# The module directory as LinuxCNC's own build rules install to it.
set(_firtp_lcnc_module_dir /usr/lib/linuxcnc/modules)
if(EXISTS /usr/share/linuxcnc/Makefile.modinc)
  file(STRINGS /usr/share/linuxcnc/Makefile.modinc _firtp_lcnc_rtlibdir REGEX "^RTLIBDIR := /")
  list(LENGTH _firtp_lcnc_rtlibdir _n)
  if(_n GREATER 0)
    list(GET _firtp_lcnc_rtlibdir -1 _line)  # the installed (not run-in-place) branch comes last
    string(REGEX REPLACE "^RTLIBDIR := *" "" _firtp_lcnc_module_dir "${_line}")
    string(STRIP "${_firtp_lcnc_module_dir}" _firtp_lcnc_module_dir)
  endif()
endif()
set(FIRTP_LINUXCNC_MODULE_DIR ${_firtp_lcnc_module_dir} CACHE PATH "LinuxCNC's realtime module directory (install-linuxcnc)")
set(FIRTP_LINUXCNC_OUTPUT_DIR ${CMAKE_BINARY_DIR}/linuxcnc)
message(STATUS "firtp: LinuxCNC modules ${FIRTP_LINUXCNC_ENABLED} (FIRTP_LINUXCNC=${FIRTP_LINUXCNC}, "
  "headers ${FIRTP_LINUXCNC_INCLUDE_DIR}, install-linuxcnc to ${FIRTP_LINUXCNC_MODULE_DIR})")

if(FIRTP_LINUXCNC_ENABLED)
  # Makefile.modinc's uspace flags (RTFLAGS, EXTRA_CFLAGS) that matter for code generation.
  set(FIRTP_LINUXCNC_COMPILE_DEFINITIONS USPACE RTAPI _GNU_SOURCE realtime __MODULE__ SIM)
  set(FIRTP_LINUXCNC_COMPILE_OPTIONS -fPIC -fno-fast-math -fno-unsafe-math-optimizations
    -fno-builtin-sin -fno-builtin-cos -fno-builtin-sincos -Wframe-larger-than=2560)
  check_cxx_compiler_flag(-mieee-fp FIRTP_HAVE_MIEEE_FP)
  if(FIRTP_HAVE_MIEEE_FP)
    list(APPEND FIRTP_LINUXCNC_COMPILE_OPTIONS -mieee-fp)
  endif()
  add_custom_target(install-linuxcnc
    COMMENT "LinuxCNC modules installed in ${FIRTP_LINUXCNC_MODULE_DIR}")
  # the way back: FILES is filled by firtp_linuxcnc_add_module (a generator expression of the list)
  add_custom_target(uninstall-linuxcnc
    COMMAND ${CMAKE_COMMAND} "-DFILES=$<GENEX_EVAL:$<TARGET_PROPERTY:uninstall-linuxcnc,FIRTP_FILES>>"
      -P ${CMAKE_CURRENT_LIST_DIR}/uninstall_linuxcnc.cmake
    COMMENT "Removing firtp's modules from ${FIRTP_LINUXCNC_MODULE_DIR}"
    VERBATIM)
else()
  add_custom_target(install-linuxcnc
    COMMAND ${CMAKE_COMMAND} -E echo "install-linuxcnc: no LinuxCNC modules were built: LinuxCNC's headers are not in ${FIRTP_LINUXCNC_INCLUDE_DIR} (linuxcnc-uspace-dev) or FIRTP_LINUXCNC is OFF"
    COMMAND ${CMAKE_COMMAND} -E false
    VERBATIM)
endif()

function(firtp_linuxcnc_add_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LIBS;INCLUDES;EXPORTS")
  if(NOT FIRTP_LINUXCNC_ENABLED)
    message(FATAL_ERROR "firtp_linuxcnc_add_module(${name}): LinuxCNC is not enabled (check FIRTP_LINUXCNC_ENABLED first)")
  endif()
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "firtp_linuxcnc_add_module(${name}): no SOURCES")
  endif()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "firtp_linuxcnc_add_module(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(target linuxcnc_${name})

  set(exports rtapi_app_main rtapi_app_exit "rtapi_info_*" ${arg_EXPORTS})
  list(JOIN exports ";\n    " global)
  set(version_script ${CMAKE_CURRENT_BINARY_DIR}/${target}.ver)
  file(CONFIGURE OUTPUT ${version_script} CONTENT "{\n  global:\n    ${global};\n  local: *;\n};\n" @ONLY)

  add_library(${target} MODULE ${arg_SOURCES})
  set_target_properties(${target} PROPERTIES
    PREFIX "" OUTPUT_NAME ${name}
    LIBRARY_OUTPUT_DIRECTORY ${FIRTP_LINUXCNC_OUTPUT_DIR}
    LINK_DEPENDS ${version_script})
  # SYSTEM: LinuxCNC's headers are not ours to fix (-Wvolatile on hal_port_*, casts).
  target_include_directories(${target} SYSTEM PRIVATE ${FIRTP_LINUXCNC_INCLUDE_DIR})
  target_include_directories(${target} PRIVATE ${arg_INCLUDES})
  target_compile_definitions(${target} PRIVATE ${FIRTP_LINUXCNC_COMPILE_DEFINITIONS})
  target_compile_options(${target} PRIVATE ${FIRTP_LINUXCNC_COMPILE_OPTIONS})
  # HAL and RTAPI symbols stay undefined: rtapi_app provides them (hal_lib, RTLD_GLOBAL).
  target_link_options(${target} PRIVATE -Wl,-Bsymbolic -Wl,--version-script,${version_script})
  target_link_libraries(${target} PRIVATE ${arg_LIBS} firtp_warnings m)

  add_custom_target(install-linuxcnc-${name}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${FIRTP_LINUXCNC_MODULE_DIR}
    # copy, then rename: a running rtapi_app may have the old file mapped
    COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:${target}> ${FIRTP_LINUXCNC_MODULE_DIR}/.${name}.so.new
    COMMAND ${CMAKE_COMMAND} -E rename ${FIRTP_LINUXCNC_MODULE_DIR}/.${name}.so.new ${FIRTP_LINUXCNC_MODULE_DIR}/${name}.so
    DEPENDS ${target}
    COMMENT "Installing ${FIRTP_LINUXCNC_MODULE_DIR}/${name}.so"
    VERBATIM)
  add_dependencies(install-linuxcnc install-linuxcnc-${name})
  set_property(TARGET uninstall-linuxcnc APPEND PROPERTY FIRTP_FILES ${FIRTP_LINUXCNC_MODULE_DIR}/${name}.so)
  set_property(GLOBAL APPEND PROPERTY FIRTP_LINUXCNC_MODULES ${name})
endfunction()
