# Edge detection tests (paper Sec. 4): grid normals, scores, region growing,
# DetectEdges on virtual scans with true-edge flags.
edgefit_add_test(edges_test
  SOURCES
    edges/grid_normals_test.cc
    edges/edge_score_test.cc
    edges/region_growing_test.cc
    edges/edge_detector_test.cc
  LIBS edgefit::edges edgefit::scanner OpenMP::OpenMP_CXX)
# Quality regression guard on the bundled robot with accessories: a full
# scene (1.7 mm), the release half (e2e); the detector runs under the
# sanitizers in edges_test's box scenes.
edgefit_add_test(edges_quality_test E2E
  SOURCES edges/edge_quality_test.cc
  LIBS edgefit::edges edgefit::scanner edgefit::scene)
