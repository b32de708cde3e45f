# Scanner layer tests: virtual TLS scanner, placements, random joints, truth.
edgefit_add_test(scanner_test
  SOURCES
    scanner/virtual_scanner_test.cc
    scanner/scan_roundtrip_test.cc
    scanner/truth_test.cc
    scanner/placement_and_joints_test.cc
    scanner/edge_metrics_test.cc
    scanner/depth_camera_test.cc
  LIBS edgefit::scanner edgefit::io OpenMP::OpenMP_CXX)
# Posed URDF models, incl. the real KUKA in ${EDGEFIT_SHARED_DIR} (skipped when absent).
edgefit_add_test(scanner_model_test
  SOURCES scanner/model_scan_test.cc
  LIBS edgefit::scanner edgefit::scene)
# Whole scenes as `edgefit scan` builds them: bundled assets and ../shared/robots.
edgefit_add_test(scanner_scene_test
  SOURCES scanner/scene_scan_test.cc
  LIBS edgefit::scanner edgefit::scene)
# The realistic sensor's effects (mixed pixels, incidence noise, stations,
# as-built surfaces, jackets).
edgefit_add_test(realistic_sensor_test
  SOURCES scanner/realistic_sensor_test.cc
  LIBS edgefit::scanner edgefit::scene)
