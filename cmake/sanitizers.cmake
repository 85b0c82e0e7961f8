# Sanitizer builds (docs/HARDENING.md).
#
#   FIRTP_SANITIZE   empty (default) | a comma-separated list of address, undefined, leak, thread,
#                    e.g. -DFIRTP_SANITIZE=address,undefined or -DFIRTP_SANITIZE=thread.
#                    Every target (libraries, tests, hal-shim, the components it dlopens) is
#                    compiled and linked with -fsanitize=...; any report stops the program
#                    (-fno-sanitize-recover=all), so a test with undefined behaviour fails.
#   FIRTP_FUZZ       OFF (default) | ON: the libFuzzer targets in tests/fuzz (clang only). The
#                    libraries they exercise get -fsanitize=fuzzer-no-link (coverage); the fuzzer
#                    executables link -fsanitize=fuzzer. Use with FIRTP_SANITIZE=address,undefined.
#
# Sanitized builds do not build the LinuxCNC modules (FIRTP_LINUXCNC is forced OFF): rtapi_app,
# which is not instrumented, dlopens them, and a sanitizer runtime must be the first library of
# the process. Their tests then report "skipped" (exit 77).
include_guard(GLOBAL)

set(FIRTP_SANITIZE "" CACHE STRING "Sanitizers: empty, or a comma-separated list of address, undefined, leak, thread")
option(FIRTP_FUZZ "Build the libFuzzer targets (clang; tests/fuzz)" OFF)

set(FIRTP_SANITIZE_FLAGS "")
if(FIRTP_SANITIZE)
  string(REPLACE "," ";" _firtp_sanitizers "${FIRTP_SANITIZE}")
  foreach(s ${_firtp_sanitizers})
    if(NOT s MATCHES "^(address|undefined|leak|thread)$")
      message(FATAL_ERROR "FIRTP_SANITIZE: unknown sanitizer '${s}' (address, undefined, leak, thread)")
    endif()
  endforeach()
  if("thread" IN_LIST _firtp_sanitizers AND ("address" IN_LIST _firtp_sanitizers OR "leak" IN_LIST _firtp_sanitizers))
    message(FATAL_ERROR "FIRTP_SANITIZE: thread cannot be combined with address or leak")
  endif()
  set(FIRTP_SANITIZE_FLAGS -fsanitize=${FIRTP_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_options(${FIRTP_SANITIZE_FLAGS})
  add_link_options(-fsanitize=${FIRTP_SANITIZE})
  if(FIRTP_LINUXCNC STREQUAL "ON")
    message(FATAL_ERROR "FIRTP_SANITIZE and FIRTP_LINUXCNC=ON: the LinuxCNC modules cannot be sanitized "
      "(rtapi_app, not instrumented, dlopens them)")
  endif()
  set(FIRTP_LINUXCNC OFF)  # a normal variable: hides the cache entry linuxcnc.cmake reads
  message(STATUS "firtp: sanitizers ${FIRTP_SANITIZE}; LinuxCNC modules not built")
endif()

if(FIRTP_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FIRTP_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
  endif()
  if(NOT FIRTP_SANITIZE)
    message(WARNING "FIRTP_FUZZ without FIRTP_SANITIZE finds crashes only: use -DFIRTP_SANITIZE=address,undefined")
  endif()
endif()

# Coverage instrumentation for a library a fuzzer exercises (no-op unless FIRTP_FUZZ).
function(firtp_fuzz_instrument)
  if(FIRTP_FUZZ)
    foreach(target ${ARGN})
      target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endforeach()
  endif()
endfunction()
