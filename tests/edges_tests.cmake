# Edge detection tests (paper Sec. 4): grid normals, scores, region growing,
# DetectEdges on virtual scans with true-edge flags.
edgefit_add_test(edges_test
  SOURCES
    edges/grid_normals_test.cc
    edges/edge_score_test.cc
    edges/region_growing_test.cc
    edges/edge_detector_test.cc
  LIBS edgefit::edges edgefit::scanner OpenMP::OpenMP_CXX)
# Quality regression guard on the bundled robot with accessories.
edgefit_add_test(edges_quality_test
  SOURCES edges/edge_quality_test.cc
  LIBS edgefit::edges edgefit::scanner edgefit::scene)
