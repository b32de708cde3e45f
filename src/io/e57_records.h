// Private: the records of an E57 CompressedVector binary section (ASTM
// E2807, 9.3-9.5) in the bitpack codec, the only codec the standard defines.
// A section is a 32-byte header and a run of packets; a data packet carries
// one bytestream buffer per prototype field, and each field's bytestream,
// concatenated over the packets, holds its values back to back: floats as
// little-endian IEEE 754, integers as (value - minimum) in
// ceil(log2(maximum - minimum + 1)) bits, least significant bit first.
#ifndef EDGEFIT_SRC_IO_E57_RECORDS_H_
#define EDGEFIT_SRC_IO_E57_RECORDS_H_

#include <cstdint>
#include <functional>
#include <vector>

#include "e57_pages.h"
#include "e57_xml.h"
#include "edgefit/core/status.h"

namespace edgefit {
namespace io_internal {

// Streams the records of one section, a block at a time: memory is one
// packet and each field's undecoded bytes, whatever the record count.
class E57RecordReader {
 public:
  // `where` names the section in messages ("f.e57: /data3D/0/points").
  E57RecordReader(E57PageReader* file, const E57Points& points, std::string where);

  // Reads and checks the section header.
  Status Start();
  // Decodes the next records, at most `max_records`, into `values`
  // (field-major: values[f * *count + r], Integer as the integer,
  // ScaledInteger scaled, Float as is). *count == 0 once all are read.
  Status Next(size_t max_records, std::vector<double>* values, size_t* count);

 private:
  struct Stream {
    std::vector<uint8_t> bytes;
    uint64_t bit = 0;  // next unread bit in `bytes`
    int bits = 0;
    uint64_t Available() const;
  };
  Status ReadPacket();

  E57PageReader* file_;
  const E57Points& points_;
  std::string where_;
  std::vector<Stream> streams_;
  uint64_t next_packet_ = 0;  // logical offset
  uint64_t section_end_ = 0;  // logical offset
  uint64_t decoded_ = 0;
  std::vector<uint8_t> packet_;
};

// Writes one section of `record_count` records starting at the writer's
// position (a multiple of 4). `fill(first, count, values)` supplies records
// [first, first + count) field-major, as E57RecordReader returns them.
// SectionBytes() gives the section's length beforehand.
class E57RecordWriter {
 public:
  using Fill = std::function<void(uint64_t first, size_t count, std::vector<double>* values)>;
  explicit E57RecordWriter(const std::vector<E57Field>& fields);

  uint64_t SectionBytes(uint64_t record_count) const;
  void Write(uint64_t record_count, const Fill& fill, E57PageWriter* out) const;

 private:
  size_t PacketBytes(size_t records) const;

  const std::vector<E57Field>& fields_;
  size_t records_per_packet_ = 0;
};

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_E57_RECORDS_H_
