// libFuzzer harness of one scan reader, chosen at compile time
// (EDGEFIT_FUZZ_FORMAT: Ptx, Pcd, Ply or E57; fuzz/CMakeLists.txt builds one
// binary each): any bytes must parse or fail with a Status, never crash,
// leak or run into undefined behaviour. For E57 the harness first writes
// every page's correct checksum, so that mutations reach the XML and the
// binary sections instead of stopping at the first page check.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "edgefit/io/e57.h"
#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/ptx.h"
#ifdef EDGEFIT_FUZZ_E57_CHECKSUMS
#include "crc32c.h"
#include "e57_pages.h"
#endif

#define EDGEFIT_CONCAT(a, b) a##b
#define EDGEFIT_PARSER(format) EDGEFIT_CONCAT(Parse, format)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  edgefit::ReadOptions options;
  options.lattice.min_valid_points = 4;  // let small inputs reach the lattice estimate
  edgefit::ScanSet scans;
  std::string content(reinterpret_cast<const char*>(data), size);
#ifdef EDGEFIT_FUZZ_E57_CHECKSUMS
  using edgefit::io_internal::kE57PageBytes;
  using edgefit::io_internal::kE57PageDataBytes;
  for (size_t page = 0; page + kE57PageBytes <= content.size(); page += kE57PageBytes) {
    const uint32_t crc = edgefit::io_internal::Crc32c(content.data() + page, kE57PageDataBytes);
    for (int k = 0; k < 4; ++k) content[page + kE57PageDataBytes + k] = static_cast<char>(crc >> (24 - 8 * k));
  }
#endif
  (void)edgefit::EDGEFIT_PARSER(EDGEFIT_FUZZ_FORMAT)(content, "fuzz", options, &scans);
  return 0;
}
