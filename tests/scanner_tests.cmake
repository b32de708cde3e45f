# Scanner layer tests: virtual TLS scanner, placements, random joints, truth.
edgefit_add_test(scanner_test
  SOURCES
    scanner/virtual_scanner_test.cc
  LIBS edgefit::scanner edgefit::io OpenMP::OpenMP_CXX)
