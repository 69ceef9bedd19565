# FSI_PYTHON: the interpreter every Python test runs under, with the project's package
# (python/fsi/) and the tests' shared helpers (tests/support/) on PYTHONPATH, as ./fsi sets it
# for everything it starts (no script edits sys.path), and the executables' folder (FSI_BIN_DIR).
set(FSI_PYTHON ${CMAKE_COMMAND} -E env "PYTHONPATH=${PROJECT_SOURCE_DIR}/python:${PROJECT_SOURCE_DIR}/tests/support"
    "FSI_BIN_DIR=${CMAKE_RUNTIME_OUTPUT_DIRECTORY}" /usr/bin/python3)

# fsi_add_python_tests: one CTest test per class of a Python unittest script.
#
#   fsi_add_python_tests(PREFIX coupled.physics SCRIPT test_coupled_physics.py LABEL coupled
#                        ENVIRONMENT "A=1" "B=2" [RUN_SERIAL]
#                        TESTS Relaxation:60 HangingFilament:90)
#
# adds coupled.physics.Relaxation (timeout 60 s) running `${FSI_PYTHON} SCRIPT -v Relaxation`
# in the script's folder. Exit code 77 means skipped (a Debian python3-* package or an
# executable the test needs is missing; the test says which).
function(fsi_add_python_tests)
  cmake_parse_arguments(ARG "RUN_SERIAL" "PREFIX;SCRIPT;LABEL" "ENVIRONMENT;TESTS" ${ARGN})
  foreach(entry ${ARG_TESTS})
    string(REPLACE ":" ";" parts ${entry})
    list(GET parts 0 class)
    list(GET parts 1 timeout)
    set(name ${ARG_PREFIX}.${class})
    add_test(NAME ${name}
             COMMAND ${FSI_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_SCRIPT} -v ${class}
             WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABEL}" TIMEOUT ${timeout}
                         ENVIRONMENT "${ARG_ENVIRONMENT}" SKIP_RETURN_CODE 77)
    if(ARG_RUN_SERIAL)
      set_tests_properties(${name} PROPERTIES RUN_SERIAL TRUE)
    endif()
  endforeach()
endfunction()
