# Runs LCM's Java class discovery on the types jar and expects every firtp_lcm type in it.
# cmake -DJAVA=... -DLCM_JAR=... -DTYPES_JAR=... -P check_types_jar.cmake
if(NOT EXISTS "${TYPES_JAR}")
  message(FATAL_ERROR "no types jar at ${TYPES_JAR}: build target firtp_lcm_types_jar")
endif()
execute_process(
  COMMAND ${JAVA} -Djava.awt.headless=true -cp ${LCM_JAR}:${TYPES_JAR} lcm.util.ClassDiscoverer
  OUTPUT_VARIABLE found ERROR_VARIABLE errors RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "ClassDiscoverer failed (${result}): ${errors}")
endif()
foreach(type axis_state_t block_t config_t control_t status_t)
  if(NOT found MATCHES "class firtp_lcm\\.${type}[\r\n]")
    message(FATAL_ERROR "firtp_lcm.${type} not found in ${TYPES_JAR}:\n${found}")
  endif()
  message(STATUS "found firtp_lcm.${type}")
endforeach()
