# io layer tests (readers, writers, interop) and the bundled sample generator.
edgefit_add_test(io_test
  SOURCES io/ptx_test.cc io/pcd_ply_test.cc io/bad_input_test.cc io/cloudcompare_test.cc
          io/sample_scan_test.cc io/e57_test.cc io/depth_frame_test.cc io/joint_states_test.cc
  LIBS edgefit::io edgefit_test_synthetic PNG::PNG liblzf::liblzf)

# Regenerates assets/samples/two_scans.ptx (see assets/samples/README.md).
add_executable(make_sample_scan scan/make_sample_scan.cc)
target_link_libraries(make_sample_scan PRIVATE edgefit::io edgefit_test_synthetic)
edgefit_set_warnings(make_sample_scan)
