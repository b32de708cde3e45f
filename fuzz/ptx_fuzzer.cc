// libFuzzer harness: any bytes given to the PTX reader must parse or fail
// with a Status, never crash, leak or run into undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "edgefit/io/ptx.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgefit::ReadOptions options;
  options.lattice.min_valid_points = 4;  // let small inputs reach the lattice estimate
  edgefit::ScanSet scans;
  const std::string_view content(reinterpret_cast<const char*>(data), size);
  (void)edgefit::ParsePtx(content, "fuzz.ptx", options, &scans);
  return 0;
}
