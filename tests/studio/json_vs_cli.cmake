# Runs `pagor register --json` and `pagor-studio --headless --json` on the same inputs and holds
# the studio's figures against the CLI's (compare_results.py).
# Variables: PAGOR, STUDIO, PYTHON, COMPARE, ARGS (a ;-list of data arguments), OUTPUT_DIR, NAME.
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(cli "${OUTPUT_DIR}/${NAME}-cli.json")
set(studio "${OUTPUT_DIR}/${NAME}-studio.json")
execute_process(COMMAND "${PAGOR}" register ${ARGS} --json "${cli}" RESULT_VARIABLE rc
                OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor register failed (${rc}): ${err}")
endif()
execute_process(COMMAND "${STUDIO}" --headless ${ARGS} --json "${studio}" --size 640x480
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor-studio failed (${rc}): ${err}")
endif()
execute_process(COMMAND "${PYTHON}" "${COMPARE}" "${cli}" "${studio}" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the studio's figures differ from the CLI's")
endif()
