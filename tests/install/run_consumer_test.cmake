# Installs the built edgefit into a scratch prefix, then configures, builds
# and runs tests/install/consumer and examples/fit_scan against it with
# find_package(edgefit).
file(REMOVE_RECURSE ${WORK_DIR})
# Libraries built with the sanitizers need them in the program that links them.
set(flags "")
if(SANITIZE)
  set(flags -DCMAKE_CXX_FLAGS=-fsanitize=address,undefined
            -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
                        -B ${WORK_DIR}/build -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${flags}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer against the installed package failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer ${SOURCE_DIR}/assets/models/balancer_arm.urdf
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "consumer said: ${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "consumer ok")
  message(FATAL_ERROR "the consumer did not run correctly: ${rc}")
endif()

# examples/fit_scan, as a user builds it against the installed package: it
# must compile and link (the fit library alone), then run: usage without
# arguments, one line naming the file for a scan that is not there.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/fit_scan
                        -B ${WORK_DIR}/fit_scan -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${flags}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring examples/fit_scan against the installed package failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/fit_scan RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building examples/fit_scan failed")
endif()
execute_process(COMMAND ${WORK_DIR}/fit_scan/fit_scan RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "usage")
  message(FATAL_ERROR "fit_scan without arguments: exit ${rc}, '${err}'")
endif()
execute_process(COMMAND ${WORK_DIR}/fit_scan/fit_scan ${SOURCE_DIR}/assets/models/balancer_arm.urdf
                        ${WORK_DIR}/no_such_scan.ptx
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "no_such_scan.ptx")
  message(FATAL_ERROR "fit_scan on a missing scan: exit ${rc}, '${err}'")
endif()
# The fit library does not link the virtual scanner (Embree).
execute_process(COMMAND ldd ${WORK_DIR}/fit_scan/fit_scan OUTPUT_VARIABLE libs RESULT_VARIABLE rc)
if(rc EQUAL 0 AND libs MATCHES "embree")
  message(FATAL_ERROR "examples/fit_scan links Embree: ${libs}")
endif()
