# Run EXE with ARGS ("|"-separated) and expect a run-time failure: exit
# status 1 and a message on stderr matching the regex EXPECT. PREPARE, when
# set, is a file to write first with the text CONTENT ("|" for line breaks).
if(PREPARE)
  string(REPLACE "|" "\n" text "${CONTENT}")
  file(WRITE ${PREPARE} "${text}")
endif()
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${EXE} ${args}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "exit status ${rc}, expected 1; stderr: ${err}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr '${err}' does not match '${EXPECT}'")
endif()
