# Correspondence search tests (paper Sec. 5.2.1): lattice vs brute force and
# kd-tree on virtual scans of a box and of the fk_arm. One process: the scans
# and the brute-force reference are built once per scene and shared by the cases.
edgefit_add_test(correspondence_test SINGLE_PROCESS COST 120
  SOURCES correspondence/lattice_search_test.cc
  LIBS edgefit::correspondence edgefit::scanner edgefit::scene edgefit::model glog::glog
       OpenMP::OpenMP_CXX)
