# Installs the built edgefit into a scratch prefix, then configures, builds
# and runs tests/install/consumer and examples/fit_scan against it with
# find_package(edgefit), as a user's project would.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()

# Configures and builds the project in `source` into ${WORK_DIR}/<name>.
function(build_against_install name source)
  set(flags "")
  if(SANITIZE)  # libraries built with the sanitizers need them in the program too
    set(flags -DCMAKE_CXX_FLAGS=-fsanitize=address,undefined
              -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${source} -B ${WORK_DIR}/${name} -G ${GENERATOR}
                          -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                          ${flags}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "configuring ${name} against the installed package failed")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/${name} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "building ${name} against the installed package failed")
  endif()
endfunction()

build_against_install(consumer ${SOURCE_DIR}/tests/install/consumer)
execute_process(COMMAND ${WORK_DIR}/consumer/consumer ${SOURCE_DIR}/assets/models/balancer_arm.urdf
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "consumer said: ${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "consumer ok")
  message(FATAL_ERROR "the consumer did not run correctly: ${rc}")
endif()

# examples/fit_scan links the fit library alone: usage without arguments,
# one line naming the file for a scan that is not there, and no Embree
# (the virtual scanner) among its libraries.
build_against_install(fit_scan ${SOURCE_DIR}/examples/fit_scan)
set(fit_scan ${WORK_DIR}/fit_scan/fit_scan)
execute_process(COMMAND ${fit_scan} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "usage")
  message(FATAL_ERROR "fit_scan without arguments: exit ${rc}, '${err}'")
endif()
execute_process(COMMAND ${fit_scan} ${SOURCE_DIR}/assets/models/balancer_arm.urdf
                        ${WORK_DIR}/no_such_scan.ptx
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "no_such_scan.ptx")
  message(FATAL_ERROR "fit_scan on a missing scan: exit ${rc}, '${err}'")
endif()
execute_process(COMMAND ldd ${fit_scan} OUTPUT_VARIABLE libs RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR libs MATCHES "embree")
  message(FATAL_ERROR "examples/fit_scan links Embree (or ldd failed): ${libs}")
endif()
