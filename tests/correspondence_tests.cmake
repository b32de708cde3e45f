# Correspondence search tests (paper Sec. 5.2.1): lattice vs brute force and
# kd-tree on virtual scans of a box and of the fk_arm.
edgefit_add_test(correspondence_test
  SOURCES correspondence/lattice_search_test.cc
  LIBS edgefit::correspondence edgefit::scanner edgefit::scene edgefit::model glog::glog
       OpenMP::OpenMP_CXX)
