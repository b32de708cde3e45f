// Private: E57's physical layout (ASTM E2807, 7.2). A file is a sequence of
// 1024-byte pages: 1020 data bytes, then the CRC-32C of those bytes stored
// big-endian. "Logical" offsets count data bytes only; the file header and
// the offsets in the XML and in section headers are physical ones.
#ifndef EDGEFIT_SRC_IO_E57_PAGES_H_
#define EDGEFIT_SRC_IO_E57_PAGES_H_

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {
namespace io_internal {

constexpr uint64_t kE57PageBytes = 1024;
constexpr uint64_t kE57PageDataBytes = 1020;

inline uint64_t E57Logical(uint64_t physical) {
  return physical / kE57PageBytes * kE57PageDataBytes + physical % kE57PageBytes;
}
inline uint64_t E57Physical(uint64_t logical) {
  return logical / kE57PageDataBytes * kE57PageBytes + logical % kE57PageDataBytes;
}

// Reads logical bytes of an E57 file held in memory or on disk. Pages are
// loaded in chunks and each page's checksum is verified when loaded, so a
// reader streaming through a file holds one chunk, never the file.
class E57PageReader {
 public:
  // `name` prefixes messages. The memory must outlive the reader.
  E57PageReader(std::string_view memory, std::string name);
  ~E57PageReader();
  E57PageReader(const E57PageReader&) = delete;
  E57PageReader& operator=(const E57PageReader&) = delete;

  // Opens `path`; fails naming the file when it cannot be read.
  Status Open(const std::string& path);

  // Checks that the file is a whole number of pages.
  Status CheckSize() const;
  uint64_t physical_size() const { return size_; }
  uint64_t logical_size() const { return size_ / kE57PageBytes * kE57PageDataBytes; }
  const std::string& name() const { return name_; }

  // Copies `n` logical bytes from logical offset `logical` to `out`. Fails on
  // a read past the end or a page whose checksum does not match.
  Status Read(uint64_t logical, size_t n, void* out);

 private:
  Status LoadChunk(uint64_t first_page);

  std::string name_;
  std::string_view memory_;
  int fd_ = -1;
  uint64_t size_ = 0;
  uint64_t chunk_first_page_ = 0;
  uint64_t chunk_pages_ = 0;
  std::vector<char> chunk_;
};

// Writes logical bytes as checksummed pages to a stream; Finish() pads the
// last page with zeros.
class E57PageWriter {
 public:
  explicit E57PageWriter(std::ostream* out) : out_(out) { page_.reserve(kE57PageBytes); }
  void Write(const void* data, size_t n);
  void WriteZeros(uint64_t n);
  uint64_t logical_position() const { return logical_; }
  uint64_t physical_position() const { return E57Physical(logical_); }
  void Finish();

 private:
  void FlushPage();

  std::ostream* out_;
  std::vector<char> page_;
  uint64_t logical_ = 0;
};

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_E57_PAGES_H_
