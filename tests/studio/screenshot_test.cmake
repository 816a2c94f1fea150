# Renders one session headless and compares it with its reference PNG.
# Variables: STUDIO, COMPARE, SESSION, REFERENCE, OUTPUT_DIR, NAME, SIZE; optional IGNORE: more
# rectangles "x,y,w,h" separated by '|' whose pixels show wall-clock times.
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(actual "${OUTPUT_DIR}/${NAME}.png")
execute_process(
  COMMAND "${STUDIO}" --headless --session "${SESSION}" --size "${SIZE}" --screenshot "${actual}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor-studio failed (${rc})")
endif()
# The status bar (bottom 28 px) shows wall-clock times, which differ from run to run.
string(REPLACE "x" ";" wh "${SIZE}")
list(GET wh 0 width)
list(GET wh 1 height)
math(EXPR status_y "${height} - 28")
set(more_ignores)
if(IGNORE)
  string(REPLACE "|" ";" rects "${IGNORE}")
  foreach(r ${rects})
    list(APPEND more_ignores --ignore "${r}")
  endforeach()
endif()
execute_process(
  COMMAND "${COMPARE}" "${REFERENCE}" "${actual}" --diff "${OUTPUT_DIR}/${NAME}.diff.png"
          --ignore "0,${status_y},${width},28" ${more_ignores}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: the rendering differs from ${REFERENCE}; new image: ${actual}, "
                      "diff: ${OUTPUT_DIR}/${NAME}.diff.png. If the change is intended, regenerate the "
                      "references: cmake --build build --target update_screenshots")
endif()
