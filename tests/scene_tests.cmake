# Scene layer tests: posed model, environment, tubes, accessories.
edgefit_add_test(scene_test
  SOURCES
    scene/model_scene_test.cc
    scene/environment_test.cc
    scene/tube_mesh_test.cc
    scene/accessories_test.cc
  LIBS edgefit::scene)
# Accessories on the real models in ${EDGEFIT_SHARED_DIR}/robots (skipped when absent).
edgefit_add_test(scene_robots_test SOURCES scene/accessories_robots_test.cc LIBS edgefit::scene)
