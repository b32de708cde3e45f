// Writes the bundled sample scan set (testing::MakeSampleScanSet) as PTX:
//   make_sample_scan assets/samples/two_scans.ptx
#include <cstdio>

#include "edgefit/io/ptx.h"
#include "scan/synthetic_scan.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.ptx\n", argv[0]);
    return 2;
  }
  const edgefit::Status status = edgefit::WritePtx(argv[1], edgefit::testing::MakeSampleScanSet());
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.message().c_str());
    return 1;
  }
  return 0;
}
