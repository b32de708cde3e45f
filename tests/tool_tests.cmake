if(TARGET edgefit)
  edgefit_add_test(cli_test SOURCES tools/cli_test.cc tools/scan_cli_test.cc
                   tools/edges_cli_test.cc tools/fit_cli_test.cc tools/batch_cli_test.cc
                   tools/bench_cli_test.cc tools/bad_input_cli_test.cc tools/cell_cli_test.cc
                   tools/report_cli_test.cc tools/world_cli_test.cc
                   LIBS nlohmann_json::nlohmann_json)
  target_compile_definitions(cli_test PRIVATE EDGEFIT_BINARY="$<TARGET_FILE:edgefit>")
  add_dependencies(cli_test edgefit)
  # edgefit batch and bench on a real one-node Slurm (scripts/slurm/): e2e,
  # it runs the same code as cli_test, through Slurm.
  add_test(NAME slurm_batch_test
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/slurm/slurm_batch_test.sh
                   $<TARGET_FILE:edgefit> ${PROJECT_SOURCE_DIR})
  set_tests_properties(slurm_batch_test PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600 RUN_SERIAL TRUE
                                                    LABELS e2e)
endif()

# cmake --install gives a package that a small consumer project and
# examples/fit_scan build against. The release half only: a check of the
# installed package, whose fit the sanitizers see in the other tests.
if(NOT EDGEFIT_SANITIZE)
  add_test(NAME install_consumer_test
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
                   -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install_consumer
                   -DGENERATOR=${CMAKE_GENERATOR}
                   -DSANITIZE=${EDGEFIT_SANITIZE}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/install/run_consumer_test.cmake)
  set_tests_properties(install_consumer_test PROPERTIES TIMEOUT 300 LABELS unit)
endif()
