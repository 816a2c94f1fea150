# A car park's pairs file opened alone in the studio runs under the indoor preset, as pagor bench
# would run it (it once ran the plans under the default classes and stopped on "label scheme
# 'indoor' has no class 'car'"). Variables: PAGOR, STUDIO, OUTPUT_DIR.
set(dir "${OUTPUT_DIR}/pairs-preset")
file(REMOVE_RECURSE "${dir}")
execute_process(COMMAND "${PAGOR}" indoor --out "${dir}" --scans 2 --seed 1 RESULT_VARIABLE rc
                OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pagor indoor failed (${rc}): ${err}")
endif()
execute_process(COMMAND "${STUDIO}" --headless --pairs "${dir}/pairs.txt"
                        --screenshot "${dir}/shot.png" --json "${dir}/result.json"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
message("exit ${rc}\nstdout: ${out}\nstderr: ${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the studio failed on the pairs file")
endif()
if(NOT out MATCHES "preset: indoor")
  message(FATAL_ERROR "the studio did not say it took the indoor preset")
endif()
file(READ "${dir}/result.json" result)
if(NOT result MATCHES "\"label_scheme\": *\"indoor\"")
  message(FATAL_ERROR "the result was not run under the indoor label scheme")
endif()
