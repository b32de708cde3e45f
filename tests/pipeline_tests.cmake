# The end-to-end fits of full scenes (label e2e: the release half only) and
# their small-scene twins (small_scene_fit_test: both halves), with the
# pipeline's unit tests.
#
# e2e: the robot fit (paper Sec. 5) on the robot scene (4 mm, about 1.9 M
# points): accuracy against the ground truth, thread-count determinism; and
# the negative set (scans that do not hold the model as given).
edgefit_add_test(robot_fit_test SINGLE_PROCESS E2E COST 90
  SOURCES pipeline/robot_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::scene edgefit::model glog::glog
       OpenMP::OpenMP_CXX)
edgefit_add_test(negative_fit_test SINGLE_PROCESS E2E COST 330
  SOURCES pipeline/negative_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::scene edgefit::model glog::glog)
# e2e: the conveyance pipeline (paper Sec. 6) on a scan of the bundled
# conveyor; --kind=auto.
edgefit_add_test(conveyance_fit_test SINGLE_PROCESS E2E COST 120
  SOURCES pipeline/conveyance_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# e2e: a robot on a linear track (../shared/robots; skips without it): the
# rail as the base, the carriage a prismatic joint.
edgefit_add_test(linear_track_fit_test SINGLE_PROCESS E2E
  SOURCES pipeline/linear_track_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model)
# e2e: the robot pipeline on a realistic scan: jackets, station residuals,
# mixed pixels, incidence noise, as-built surfaces.
edgefit_add_test(realistic_fit_test SINGLE_PROCESS E2E COST 170
  SOURCES pipeline/realistic_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# e2e: the cell fit: every instance of a model in a virtual cell, the
# background left.
edgefit_add_test(cell_fit_test SINGLE_PROCESS E2E COST 50
  SOURCES pipeline/cell_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# e2e: the robot seen by a virtual depth camera (scanner/depth_camera.h),
# fitted as a real frame is: any mounting, noise-scaled verdicts.
edgefit_add_test(depth_frame_fit_test SINGLE_PROCESS E2E COST 40
  SOURCES pipeline/depth_frame_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::model glog::glog)
# The small-scene twins of the e2e fits above (8-10 mm spacing), a process
# each (they run in parallel; each scans its own scene).
edgefit_add_test(small_scene_fit_test
  SOURCES pipeline/small_scene_fit_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::scanner edgefit::scene edgefit::model glog::glog)
# Unit tests: the instance crop, result.json of a fit that stopped early,
# the survey's frame and the stations' corrections, the joint trust rules.
edgefit_add_test(pipeline_unit_test
  SOURCES pipeline/instance_crop_test.cc pipeline/result_json_test.cc pipeline/stations_test.cc
          pipeline/noise_scale_test.cc pipeline/joint_trust_test.cc pipeline/quality_test.cc
  LIBS edgefit::pipeline edgefit::bench edgefit::model edgefit_test_synthetic)
# e2e: real depth frames of a real robot (../shared/data/real; skips
# without it): the calibration with its recorded joints (frames 002, 003),
# and every joint fitted, against the robot's readings (frame 003; frame 004
# beside clutter).
edgefit_add_test(real_frame_fit_test SINGLE_PROCESS E2E COST 150
  SOURCES pipeline/real_frame_fit_test.cc
  LIBS edgefit::pipeline edgefit::io edgefit::model nlohmann_json::nlohmann_json)
