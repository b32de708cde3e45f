# Warnings and sanitizers in one place. Applied per target through
# edgefit_set_warnings(<target>), never through global flags.
function(edgefit_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(EDGEFIT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

if(EDGEFIT_BUILD_FUZZERS)
  # Every library instrumented for libFuzzer's coverage, ASan and UBSan;
  # the harnesses link the fuzzer's main (fuzz/CMakeLists.txt). Clang only.
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "EDGEFIT_BUILD_FUZZERS needs clang (CXX=clang++; scripts/fuzz.sh)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
elseif(EDGEFIT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# Add a library of the edgefit package: edgefit_<name>, alias edgefit::<name>.
function(edgefit_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  add_library(edgefit_${name} ${ARG_SOURCES})
  add_library(edgefit::${name} ALIAS edgefit_${name})
  set_target_properties(edgefit_${name} PROPERTIES EXPORT_NAME ${name}
                        POSITION_INDEPENDENT_CODE ON)
  target_compile_features(edgefit_${name} PUBLIC cxx_std_17)
  target_include_directories(edgefit_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(edgefit_${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS})
  edgefit_set_warnings(edgefit_${name})
  install(TARGETS edgefit_${name} EXPORT edgefitTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
