# fsi_add_python_tests: one CTest test per class of a Python unittest script.
#
#   fsi_add_python_tests(PREFIX coupled.physics SCRIPT test_coupled_physics.py LABEL coupled
#                        ENVIRONMENT "A=1" "B=2" [RUN_SERIAL]
#                        TESTS Relaxation:60 HangingFilament:90)
#
# adds coupled.physics.Relaxation (timeout 60 s) running `/usr/bin/python3 SCRIPT -v Relaxation`
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
             COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_SCRIPT} -v ${class}
             WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABEL}" TIMEOUT ${timeout}
                         ENVIRONMENT "${ARG_ENVIRONMENT}" SKIP_RETURN_CODE 77)
    if(ARG_RUN_SERIAL)
      set_tests_properties(${name} PROPERTIES RUN_SERIAL TRUE)
    endif()
  endforeach()
endfunction()
