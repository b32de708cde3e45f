# The end-to-end robot fit (paper Sec. 5) on a small virtual scan: accuracy
# against the ground truth, thread-count determinism; the negative set (scans
# that do not hold the model as given).
edgefit_add_test(pipeline_test SINGLE_PROCESS
  SOURCES pipeline/robot_fit_test.cc pipeline/negative_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::scene edgefit::model glog::glog
       OpenMP::OpenMP_CXX)
# The conveyance pipeline (paper Sec. 6) on a small virtual scan of the
# bundled conveyor; --kind=auto.
edgefit_add_test(conveyance_fit_test SINGLE_PROCESS
  SOURCES pipeline/conveyance_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# A robot on a linear track (../shared/robots; skips without it): the rail
# as the base, the carriage a prismatic joint.
edgefit_add_test(linear_track_fit_test SINGLE_PROCESS
  SOURCES pipeline/linear_track_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model)
# The robot pipeline on a small realistic scan: jackets, station residuals,
# mixed pixels, incidence noise, as-built surfaces.
edgefit_add_test(realistic_fit_test SINGLE_PROCESS
  SOURCES pipeline/realistic_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# The cell fit: every instance of a model in a small virtual cell, the
# background left; the instance crop.
edgefit_add_test(cell_fit_test SINGLE_PROCESS
  SOURCES pipeline/cell_fit_test.cc pipeline/instance_crop_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model edgefit_test_synthetic glog::glog)
