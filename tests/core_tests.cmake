edgefit_add_test(core_test SOURCES core/status_test.cc core/atomic_file_test.cc core/mapped_file_test.cc
                 core/pose_test.cc
                 LIBS edgefit::core)
