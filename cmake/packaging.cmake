# Installing firtp: `cmake --install BUILD --prefix P` and the Debian package (CPack DEB,
# `cpack --config BUILD/CPackConfig.cmake` or the `package` target). Included last by the top-level
# CMakeLists.txt, after every target exists.
#
# Layout under the prefix (GNUInstallDirs):
#   bin/                          firtp, firtp-hal, firtp-lcm-dump, firtp-tp-check, firtp-lcm-spy,
#                                 firtp-lcm-bridge
#   lib/firtp/                    hal-shim's firtp.so (firtp run/serve and firtp-hal load it from
#                                 ../lib/firtp next to their program) and its runtime libfirtp_hal_shim.so
#   FIRTP_INSTALL_MODULEDIR       the LinuxCNC modules firtp.so and firtp_tp.so; relative to the
#                                 prefix, lib/linuxcnc/modules by default: with the prefix /usr
#                                 (the package) that is where rtapi_app loads modules from
#   share/firtp/lcm-types/        the .lcm messages; share/java/firtp_lcm_types.jar for lcm-spy
#   share/man/man1, man9          firtp(1), firtp(9), firtp_tp(9), gzip'd
#   share/doc/firtp/              README, licence, docs, examples/ (programs, INIs, HAL files,
#                                 LinuxCNC configurations)
include_guard(GLOBAL)
include(GNUInstallDirs)

# rtapi_app's module directory relative to /usr (the package's prefix): RTLIBDIR of Makefile.modinc.
set(_firtp_moduledir lib/linuxcnc/modules)
if(FIRTP_LINUXCNC_MODULE_DIR MATCHES "^/usr/(.+)$")
  set(_firtp_moduledir ${CMAKE_MATCH_1})
endif()
set(FIRTP_INSTALL_MODULEDIR ${_firtp_moduledir} CACHE STRING
  "Where the LinuxCNC modules are installed, relative to the prefix (rtapi_app's: RTLIBDIR under /usr)")
set(FIRTP_INSTALL_PKGLIBDIR lib/firtp)  # fixed: the programs find it as ../lib/firtp

# hal-shim's runtime is a private shared library beside hal-shim's firtp.so; the programs and the
# module find it through a RUNPATH relative to themselves (so any prefix works).
set_target_properties(firtp firtp_hal PROPERTIES INSTALL_RPATH "$ORIGIN/../${FIRTP_INSTALL_PKGLIBDIR}")
set_target_properties(firtp_module PROPERTIES INSTALL_RPATH "$ORIGIN")
install(TARGETS firtp firtp_hal firtp_lcm_dump firtp_tp_check RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET firtp_lcm_bridge)  # LCM for a running LinuxCNC (loadusr), built with the LinuxCNC modules
  install(TARGETS firtp_lcm_bridge RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(TARGETS firtp_module firtp_hal_shim LIBRARY DESTINATION ${FIRTP_INSTALL_PKGLIBDIR})
if(FIRTP_LINUXCNC_ENABLED)
  install(TARGETS linuxcnc_firtp linuxcnc_firtp_tp LIBRARY DESTINATION ${FIRTP_INSTALL_MODULEDIR})
endif()

file(GLOB _firtp_lcm_types CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/lcm-types/*.lcm)
install(FILES ${_firtp_lcm_types} DESTINATION ${CMAKE_INSTALL_DATADIR}/firtp/lcm-types)
if(TARGET firtp_lcm_types_jar)
  install(FILES ${FIRTP_LCM_TYPES_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/java)
endif()
install(PROGRAMS ${CMAKE_SOURCE_DIR}/lcm-types/lcm-spy.sh DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME firtp-lcm-spy)

# Man pages compressed as Debian installs them (gzip -n: the same bytes every build).
find_program(FIRTP_GZIP gzip REQUIRED)
set(_firtp_man_gz)
foreach(page firtp.1 firtp.9 firtp_tp.9)
  set(gz ${CMAKE_BINARY_DIR}/man/${page}.gz)
  add_custom_command(OUTPUT ${gz}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
    COMMAND sh -c "'${FIRTP_GZIP}' -9 -n -c '${CMAKE_SOURCE_DIR}/docs/man/${page}' > '${gz}'"
    DEPENDS ${CMAKE_SOURCE_DIR}/docs/man/${page} VERBATIM)
  string(REGEX REPLACE ".*\\." "" section ${page})
  install(FILES ${gz} DESTINATION ${CMAKE_INSTALL_MANDIR}/man${section})
  list(APPEND _firtp_man_gz ${gz})
endforeach()
add_custom_target(firtp_man_pages ALL DEPENDS ${_firtp_man_gz})

install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${CMAKE_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)  # Debian's place
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs PATTERN man EXCLUDE)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
  USE_SOURCE_PERMISSIONS PATTERN __pycache__ EXCLUDE)

# The Debian package. Depends: the Debian 12 packages of the libraries the installed programs and
# modules load (tests/install/deb_contents.sh checks every NEEDED library against this list) and
# the LinuxCNC whose rtapi_app and motmod load the modules.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME firtp)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR firtp)
set(CPACK_PACKAGE_CONTACT "firtp developers <firtp@localhost>")  # placeholder: the project has no address yet
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "FIR-filter corner smoothing trajectory planner for LinuxCNC")
set(CPACK_PACKAGE_DESCRIPTION "Kinematic corner smoothing with FIR filters (Sencer, Ishizaki, Shamoto, CIRP Annals 2015):
the HAL component firtp.so, the trajectory-planner module firtp_tp ([TRAJ]TPMOD = firtp_tp),
the firtp command (plan, run, serve, host, simulate) and the LCM messages and tools.")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libc6 (>= 2.36), libstdc++6 (>= 12), libgcc-s1 (>= 3.0), libboost-program-options1.74.0, liblcm1 (>= 1.3.1)")
if(FIRTP_LINUXCNC_ENABLED)  # the modules: rtapi_app, motmod, liblinuxcncini
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", linuxcnc-uspace (>= 2.9)")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox, liblcm-bin")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "liblcm-java, libjchart2d-java, default-jre")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
set(CPACK_STRIP_FILES TRUE)
set(CPACK_OUTPUT_FILE_PREFIX ${CMAKE_BINARY_DIR}/package)
include(CPack)
