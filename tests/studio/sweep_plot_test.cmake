# Runs `pagor sweep ... --plot` and compares the PNG with its reference.
# Variables: PAGOR, COMPARE, ARGS (the sweep's arguments), REFERENCE, OUTPUT_DIR.
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(actual "${OUTPUT_DIR}/sweep_plot.png")
execute_process(COMMAND "${PAGOR}" ${ARGS} --plot "${actual}" --plot-csv "${OUTPUT_DIR}/sweep_plot.csv"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor sweep failed (${rc})")
endif()
execute_process(
  COMMAND "${COMPARE}" "${REFERENCE}" "${actual}" --diff "${OUTPUT_DIR}/sweep_plot.diff.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sweep_plot: the plot differs from ${REFERENCE}; new image: ${actual}. If the "
                      "change is intended: cmake --build build --target update_screenshots")
endif()
