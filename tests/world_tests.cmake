# The planning world written from fitted machines, and its clearance (src/world).
edgefit_add_test(world_test SOURCES world/planning_world_test.cc world/clearance_test.cc
  world/least_distance_test.cc world/scanned_world_test.cc
  LIBS edgefit::world edgefit::scanner edgefit::scene edgefit::io tinyxml2::tinyxml2 octomap)

# edgefit clearance against an independent library: Open3D (Debian's
# python3-open3d, for Debian's own python3) loads the world's files and
# measures the same distances. Skipped (exit 77) where it is absent.
if(NOT EDGEFIT_SANITIZE)
  if(EXISTS /usr/bin/python3)
    set(edgefit_debian_python /usr/bin/python3)
  else()
    find_package(Python3 REQUIRED COMPONENTS Interpreter)
    set(edgefit_debian_python ${Python3_EXECUTABLE})
  endif()
  add_test(NAME world_open3d_test
           COMMAND ${edgefit_debian_python} ${CMAKE_CURRENT_SOURCE_DIR}/world/open3d_clearance_check.py
                   $<TARGET_FILE:edgefit> ${PROJECT_SOURCE_DIR})
  set_tests_properties(world_open3d_test PROPERTIES TIMEOUT 300 LABELS e2e SKIP_RETURN_CODE 77)
endif()
