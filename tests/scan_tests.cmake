# Scan layer tests. The synthetic scanner is test-only code shared with the io tests.
add_library(edgefit_test_synthetic STATIC scan/synthetic_scan.cc)
target_link_libraries(edgefit_test_synthetic PUBLIC edgefit::scan)
target_include_directories(edgefit_test_synthetic PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
edgefit_set_warnings(edgefit_test_synthetic)

edgefit_add_test(scan_test
  SOURCES scan/scan_lattice_test.cc scan/projective_lattice_test.cc scan/lattice_estimation_test.cc
          scan/scan_noise_test.cc scan/silhouette_mixed_pixels_test.cc scan/organized_scan_test.cc
  LIBS edgefit::scan edgefit_test_synthetic)
