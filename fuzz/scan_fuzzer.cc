// libFuzzer harness of one scan reader, chosen at compile time
// (EDGEFIT_FUZZ_FORMAT: Ptx, Pcd or Ply; fuzz/CMakeLists.txt builds one
// binary each): any bytes must parse or fail with a Status, never crash,
// leak or run into undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/ptx.h"

#define EDGEFIT_CONCAT(a, b) a##b
#define EDGEFIT_PARSER(format) EDGEFIT_CONCAT(Parse, format)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgefit::ReadOptions options;
  options.lattice.min_valid_points = 4;  // let small inputs reach the lattice estimate
  edgefit::ScanSet scans;
  const std::string_view content(reinterpret_cast<const char*>(data), size);
  (void)edgefit::EDGEFIT_PARSER(EDGEFIT_FUZZ_FORMAT)(content, "fuzz", options, &scans);
  return 0;
}
