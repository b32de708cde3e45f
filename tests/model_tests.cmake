# Model layer tests: kinematics, URDF/mesh loading, composition, sampling, edges.
edgefit_add_test(model_test
  SOURCES
    model/triangle_mesh_test.cc
    model/kinematic_model_test.cc
    model/loop_closure_test.cc
    model/mesh_loader_test.cc
    model/urdf_loader_test.cc
    model/composition_test.cc
    model/calibrated_urdf_test.cc
    model/surface_sampler_test.cc
    model/sharp_edges_test.cc
    model/joint_values_test.cc
    model/frozen_joints_test.cc
  LIBS edgefit::model)
# The real models in ${EDGEFIT_SHARED_DIR}/robots (skipped when absent).
edgefit_add_test(model_robots_test SOURCES model/robots_test.cc LIBS edgefit::model)
