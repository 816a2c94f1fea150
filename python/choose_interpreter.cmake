# pagor_choose_python_interpreter(): sets Python3_EXECUTABLE (cached) to an interpreter the module
# can be built for and tested with: it has its development headers (Python.h) and imports numpy,
# and pytest too when the tests are built. Given -DPython3_EXECUTABLE=..., that one is checked;
# otherwise the candidates are tried in order, the first that works is taken: the first python3
# on the PATH, then the system's /usr/bin/python3 (a pyenv or conda python3 often comes first on
# the PATH without numpy, while Debian's has python3-numpy and python3-pytest). None working is a
# configure error naming what each candidate lacks and the two ways out.

# What `python` lacks, as text in `out` (empty when it has everything).
function(pagor_python_lacks python out)
  set(modules numpy)
  if(PAGOR_BUILD_TESTS)
    list(APPEND modules pytest)
  endif()
  string(JOIN "\", \"" quoted ${modules})
  set(probe "import importlib.util, os, sysconfig
missing = [m for m in (\"${quoted}\",) if importlib.util.find_spec(m) is None]
if not os.path.exists(os.path.join(sysconfig.get_paths()['include'], 'Python.h')):
    missing.append('its development headers (Python.h)')
print(', '.join(missing))")
  execute_process(COMMAND ${python} -c "${probe}" RESULT_VARIABLE rc OUTPUT_VARIABLE lacks
                  ERROR_VARIABLE error OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    string(STRIP "${error}" error)
    set(lacks "a working interpreter (${error})")
  endif()
  set(${out} "${lacks}" PARENT_SCOPE)
endfunction()

function(pagor_choose_python_interpreter)
  set(way_out "Install what is missing (Debian: sudo apt-get install python3-dev python3-numpy \
python3-pytest pybind11-dev, or bash .ci/install-deps), choose another interpreter with \
-DPython3_EXECUTABLE=/path/to/python3, or configure with -DPAGOR_BUILD_PYTHON=OFF to build \
without the Python module.")
  if(Python3_EXECUTABLE)
    pagor_python_lacks("${Python3_EXECUTABLE}" lacks)
    if(lacks)
      message(FATAL_ERROR "Python module: ${Python3_EXECUTABLE} (-DPython3_EXECUTABLE) lacks "
                          "${lacks}. ${way_out}")
    endif()
    return()
  endif()
  find_program(path_python3 python3 NO_CACHE)
  set(candidates)
  foreach(candidate ${path_python3} /usr/bin/python3)
    if(EXISTS "${candidate}")
      list(APPEND candidates "${candidate}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES candidates)
  set(report)
  foreach(candidate ${candidates})
    pagor_python_lacks("${candidate}" lacks)
    if(NOT lacks)
      message(STATUS "Python module: ${candidate} has numpy, pytest and its headers")
      set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH "The Python the module is built for")
      return()
    endif()
    string(APPEND report "\n  ${candidate} lacks ${lacks}")
    message(STATUS "Python module: skipping ${candidate}: it lacks ${lacks}")
  endforeach()
  if(NOT candidates)
    set(report "\n  no python3 on the PATH, and no /usr/bin/python3")
  endif()
  message(FATAL_ERROR "Python module (PAGOR_BUILD_PYTHON is ON): no interpreter can build and "
                      "test it:${report}\n${way_out}")
endfunction()
