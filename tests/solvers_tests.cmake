# Weighted, constrained ICP engine (paper Sec. 5.1.2, 5.2.2, 6.2.2):
# synthetic recovery to 1e-6 and within noise, parameterisations, stops,
# determinism; the 2D grid's radius queries; the height map's convex tips and the symmetry axis (6.1);
# on virtual scans: the cable-tube outlier case with edges and
# the Eq. (9) joint sweep; the floor and the rough base registration
# (Sec. 5.1.1); the whole-chain refinement and its covariance on the
# bundled robot; the final basin check bringing a flipped wrist back; the
# pair sweep of a round arm and the bend below it.
edgefit_add_test(solvers_test
  SOURCES
    solvers/link_motion_test.cc
    solvers/weighted_icp_test.cc
    solvers/height_map_test.cc
    solvers/symmetry_axis_test.cc
    solvers/body_test.cc
    solvers/observability_test.cc
    solvers/base_hypotheses_test.cc
    solvers/pose_evidence_test.cc
    solvers/point_grid2_test.cc
  LIBS edgefit::solvers edgefit::model OpenMP::OpenMP_CXX)
# On virtual scans of whole robots: the release half only (label e2e). Under
# ASan + UBSan it took 490 s of the sanitizer half's CPU; the same stages run
# there in small_scene_fit_test's every-stage fit.
edgefit_add_test(solvers_scan_test SINGLE_PROCESS E2E COST 300
  SOURCES solvers/tube_outlier_test.cc solvers/joint_sweep_test.cc solvers/base_rough_test.cc
          solvers/floor_height_test.cc
          solvers/chain_refinement_test.cc solvers/final_basins_test.cc solvers/coverings_test.cc
          solvers/pose_voting_test.cc solvers/up_direction_test.cc solvers/pair_sweep_test.cc
  LIBS edgefit::solvers edgefit::edges edgefit::scanner edgefit::scene edgefit::model glog::glog
       OpenMP::OpenMP_CXX)
