# Fails when docs/config.md differs from what `pagor config --describe` prints now.
# Variables: PAGOR (the tool), REFERENCE (docs/config.md), OUTPUT (where to write the new text).
execute_process(COMMAND ${PAGOR} config --describe OUTPUT_FILE ${OUTPUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor config --describe failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUTPUT} ${REFERENCE} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "docs/config.md is out of date: regenerate it with "
                      "`cmake --build build --target update_config_docs` (new text: ${OUTPUT})")
endif()
message("docs/config.md is the generated reference")
