# Run EXE with ARGS ("|"-separated) and expect a usage error: exit status 2,
# nothing on stdout, exactly one line on stderr matching the regex EXPECT.
# STATUS (optional) expects another exit status: 1 for a run-time failure.
# PREPARE (optional) is a file to write first with the text CONTENT ("|"
# for line breaks).
if(NOT DEFINED STATUS)
  set(STATUS 2)
endif()
if(PREPARE)
  string(REPLACE "|" "\n" text "${CONTENT}")
  file(WRITE ${PREPARE} "${text}")
endif()
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${EXE} ${args}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "\n$" "" line "${err}")
if(NOT rc EQUAL STATUS)
  message(FATAL_ERROR "exit status ${rc}, expected ${STATUS}; stderr: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "unexpected output on stdout: ${out}")
endif()
if(line MATCHES "\n")
  message(FATAL_ERROR "more than one line on stderr: ${err}")
endif()
if(NOT line MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr '${line}' does not match '${EXPECT}'")
endif()
