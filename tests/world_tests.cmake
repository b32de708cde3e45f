# The planning world written from fitted machines, and its clearance (src/world).
edgefit_add_test(world_test SOURCES world/planning_world_test.cc world/clearance_test.cc
  LIBS edgefit::world edgefit::io tinyxml2::tinyxml2 octomap)
