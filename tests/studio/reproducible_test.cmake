# Renders one session headless twice and requires the two PNGs to be equal byte for byte (the
# headless studio hides wall-clock times), so that a checksum can stand for the picture.
# Variables: STUDIO, SESSION, OUTPUT_DIR, NAME, SIZE.
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(sums)
foreach(run 1 2)
  set(png "${OUTPUT_DIR}/${NAME}.run${run}.png")
  file(REMOVE "${png}")
  execute_process(
    COMMAND "${STUDIO}" --headless --session "${SESSION}" --size "${SIZE}" --screenshot "${png}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pagor-studio failed (${rc})")
  endif()
  file(SHA256 "${png}" sum)
  message("${png}: sha256 ${sum}")
  list(APPEND sums ${sum})
endforeach()
list(GET sums 0 first)
list(GET sums 1 second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "${NAME}: two headless renders of the same session differ "
                      "(${OUTPUT_DIR}/${NAME}.run1.png, ${OUTPUT_DIR}/${NAME}.run2.png)")
endif()
