#include "e57_records.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "edgefit/core/little_endian.h"


namespace edgefit {
namespace io_internal {
namespace {

constexpr size_t kSectionHeaderBytes = 32;
constexpr size_t kPacketMaxBytes = 65536;
constexpr uint8_t kIndexPacket = 0, kDataPacket = 1, kEmptyPacket = 2;

void AppendLe(uint64_t v, int bytes, std::vector<uint8_t>* out) {
  out->resize(out->size() + static_cast<size_t>(bytes));
  StoreUintLE(v, bytes, out->data() + out->size() - static_cast<size_t>(bytes));
}

// `n` (1..64) bits starting at bit `bit` of `bytes`, least significant first.
uint64_t ExtractBits(const std::vector<uint8_t>& bytes, uint64_t bit, int n) {
  const size_t byte = static_cast<size_t>(bit >> 3);
  const int shift = static_cast<int>(bit & 7);
  const int have = static_cast<int>(std::min<size_t>(8, bytes.size() - byte));
  uint64_t v = LoadUintLE(bytes.data() + byte, have) >> shift;
  if (shift + n > 64) v |= static_cast<uint64_t>(bytes[byte + 8]) << (64 - shift);
  return n < 64 ? v & ((uint64_t{1} << n) - 1) : v;
}

// Appends values of `n` bits, least significant bit first.
class BitWriter {
 public:
  explicit BitWriter(std::vector<uint8_t>* out) : out_(out) {}
  void Put(uint64_t v, int n) {
    if (n == 0) return;
    acc_ |= v << used_;
    if (used_ + n >= 64) {
      AppendLe(acc_, 8, out_);
      acc_ = used_ == 0 ? 0 : v >> (64 - used_);
      used_ = used_ + n - 64;
    } else {
      used_ += n;
    }
  }
  void Finish() { AppendLe(acc_, (used_ + 7) / 8, out_); acc_ = 0; used_ = 0; }

 private:
  std::vector<uint8_t>* out_;
  uint64_t acc_ = 0;
  int used_ = 0;
};

size_t Pad4(size_t n) { return (n + 3) / 4 * 4; }

}  // namespace

uint64_t E57RecordReader::Stream::Available() const {
  if (bits == 0) return std::numeric_limits<uint64_t>::max();
  return (bytes.size() * 8 - bit) / static_cast<uint64_t>(bits);
}

E57RecordReader::E57RecordReader(E57PageReader* file, const E57Points& points, std::string where)
    : file_(file), points_(points), where_(std::move(where)), streams_(points.fields.size()) {
  for (size_t f = 0; f < streams_.size(); ++f) streams_[f].bits = points.fields[f].Bits();
}

Status E57RecordReader::Start() {
  if (points_.file_offset % kE57PageBytes >= kE57PageDataBytes) {
    return Status::Error(where_ + ": fileOffset " + std::to_string(points_.file_offset) +
                         " points into a page checksum");
  }
  const uint64_t start = E57Logical(points_.file_offset);
  uint8_t h[kSectionHeaderBytes];
  EDGEFIT_RETURN_IF_ERROR(file_->Read(start, sizeof(h), h));
  bool reserved_zero = true;
  for (int k = 1; k < 8; ++k) reserved_zero = reserved_zero && h[k] == 0;
  if (h[0] != 1 || !reserved_zero) {
    return Status::Error(where_ + ": no CompressedVector section header at byte " +
                         std::to_string(points_.file_offset) + " (section id " + std::to_string(h[0]) + ")");
  }
  const uint64_t length = LoadUintLE(h + 8, 8);
  const uint64_t data = LoadUintLE(h + 16, 8);
  if (length < kSectionHeaderBytes || length % 4 != 0 || length > file_->logical_size() - start) {
    return Status::Error(where_ + ": the section header's length " + std::to_string(length) +
                         " does not fit the file");
  }
  section_end_ = start + length;
  next_packet_ = data % kE57PageBytes < kE57PageDataBytes ? E57Logical(data) : 0;
  if (points_.record_count > 0 && (next_packet_ < start + kSectionHeaderBytes || next_packet_ >= section_end_)) {
    return Status::Error(where_ + ": the section's data offset " + std::to_string(data) +
                         " lies outside the section");
  }
  return Status::Ok();
}

Status E57RecordReader::ReadPacket() {
  const std::string at = where_ + ": packet at byte " + std::to_string(E57Physical(next_packet_));
  if (section_end_ - next_packet_ < 4) {
    return Status::Error(where_ + ": the section ends after " + std::to_string(decoded_) + " of " +
                         std::to_string(points_.record_count) + " records (file truncated or recordCount wrong)");
  }
  uint8_t head[4];
  EDGEFIT_RETURN_IF_ERROR(file_->Read(next_packet_, 4, head));
  const uint64_t length = LoadUintLE(head + 2, 2) + 1;
  if (length > section_end_ - next_packet_) return Status::Error(at + ": runs past the section's end");
  if (head[0] == kDataPacket) {
    packet_.resize(static_cast<size_t>(length));
    EDGEFIT_RETURN_IF_ERROR(file_->Read(next_packet_, packet_.size(), packet_.data()));
    const size_t count = length >= 6 ? static_cast<size_t>(LoadUintLE(packet_.data() + 4, 2)) : 0;
    if (count != streams_.size()) {
      return Status::Error(at + ": " + std::to_string(count) + " bytestreams for a prototype of " +
                           std::to_string(streams_.size()) + " fields");
    }
    size_t offset = 6 + 2 * count;
    if (offset > length) return Status::Error(at + ": too short for its bytestream lengths");
    for (size_t s = 0; s < count; ++s) {
      const size_t n = static_cast<size_t>(LoadUintLE(packet_.data() + 6 + 2 * s, 2));
      if (n > length - offset) return Status::Error(at + ": bytestream " + std::to_string(s) + " runs past the packet");
      streams_[s].bytes.insert(streams_[s].bytes.end(), packet_.data() + offset, packet_.data() + offset + n);
      offset += n;
    }
  } else if (head[0] != kIndexPacket && head[0] != kEmptyPacket) {
    return Status::Error(at + ": unknown packet type " + std::to_string(head[0]));
  }
  next_packet_ += length;
  return Status::Ok();
}

Status E57RecordReader::Next(size_t max_records, std::vector<double>* values, size_t* count) {
  const uint64_t remaining = points_.record_count - decoded_;
  uint64_t n = 0;
  while (remaining > 0) {
    n = std::min<uint64_t>(remaining, max_records);
    for (const Stream& s : streams_) n = std::min(n, s.Available());
    if (n > 0) break;
    EDGEFIT_RETURN_IF_ERROR(ReadPacket());
  }
  *count = static_cast<size_t>(n);
  values->resize(streams_.size() * *count);
  for (size_t f = 0; f < streams_.size(); ++f) {
    Stream& s = streams_[f];
    const E57Field& field = points_.fields[f];
    double* out = values->data() + f * *count;
    for (size_t r = 0; r < *count; ++r, s.bit += static_cast<uint64_t>(s.bits)) {
      if (field.type == E57Field::Type::kFloat) {
        const uint8_t* p = s.bytes.data() + (s.bit >> 3);
        if (field.single) {
          float v;
          std::memcpy(&v, p, 4);
          out[r] = v;
        } else {
          std::memcpy(&out[r], p, 8);
        }
        continue;
      }
      const uint64_t raw = (s.bits == 0 ? 0 : ExtractBits(s.bytes, s.bit, s.bits)) +
                           static_cast<uint64_t>(field.minimum);
      const double v = static_cast<double>(static_cast<int64_t>(raw));
      out[r] = field.type == E57Field::Type::kScaledInteger ? v * field.scale + field.offset : v;
    }
    const size_t consumed = static_cast<size_t>(s.bit >> 3);
    s.bytes.erase(s.bytes.begin(), s.bytes.begin() + static_cast<std::ptrdiff_t>(consumed));
    s.bit -= consumed * 8;
  }
  decoded_ += n;
  return Status::Ok();
}

E57RecordWriter::E57RecordWriter(const std::vector<E57Field>& fields) : fields_(fields) {
  size_t bits = 0;
  for (const E57Field& f : fields_) bits += static_cast<size_t>(f.Bits());
  const size_t payload = kPacketMaxBytes - 6 - 2 * fields_.size() - 4;
  // A multiple of 64 records: every bytestream buffer but the last packet's
  // then ends on a 64-bit word, as readers with word registers expect.
  records_per_packet_ = std::max<size_t>(64, payload * 8 / std::max<size_t>(bits, 1) / 64 * 64);
}

size_t E57RecordWriter::PacketBytes(size_t records) const {
  size_t bytes = 6 + 2 * fields_.size();
  for (const E57Field& f : fields_) bytes += (records * static_cast<size_t>(f.Bits()) + 7) / 8;
  return Pad4(bytes);
}

uint64_t E57RecordWriter::SectionBytes(uint64_t record_count) const {
  const uint64_t full = record_count / records_per_packet_;
  const size_t rest = static_cast<size_t>(record_count % records_per_packet_);
  return kSectionHeaderBytes + full * PacketBytes(records_per_packet_) + (rest > 0 ? PacketBytes(rest) : 0);
}

void E57RecordWriter::Write(uint64_t record_count, const Fill& fill, E57PageWriter* out) const {
  std::vector<uint8_t> bytes;
  bytes.push_back(1);  // CompressedVector section
  bytes.resize(8, 0);
  AppendLe(SectionBytes(record_count), 8, &bytes);
  AppendLe(E57Physical(out->logical_position() + kSectionHeaderBytes), 8, &bytes);
  AppendLe(0, 8, &bytes);  // no index packet
  out->Write(bytes.data(), bytes.size());
  std::vector<double> values;
  std::vector<std::vector<uint8_t>> streams(fields_.size());
  for (uint64_t first = 0; first < record_count; first += records_per_packet_) {
    const size_t count = static_cast<size_t>(std::min<uint64_t>(records_per_packet_, record_count - first));
    fill(first, count, &values);
    for (size_t f = 0; f < fields_.size(); ++f) {
      const E57Field& field = fields_[f];
      const double* in = values.data() + f * count;
      streams[f].clear();
      BitWriter writer(&streams[f]);
      for (size_t r = 0; r < count; ++r) {
        if (field.type == E57Field::Type::kFloat) {
          uint64_t word = 0;
          if (field.single) {
            const float v = static_cast<float>(in[r]);
            uint32_t w32;
            std::memcpy(&w32, &v, 4);
            word = w32;
          } else {
            std::memcpy(&word, &in[r], 8);
          }
          writer.Put(word, field.Bits());
          continue;
        }
        double raw = field.type == E57Field::Type::kScaledInteger ? (in[r] - field.offset) / field.scale : in[r];
        raw = std::clamp(std::round(raw), static_cast<double>(field.minimum), static_cast<double>(field.maximum));
        writer.Put(static_cast<uint64_t>(static_cast<int64_t>(raw)) - static_cast<uint64_t>(field.minimum),
                   field.Bits());
      }
      writer.Finish();
    }
    const size_t length = PacketBytes(count);
    bytes.assign({kDataPacket, 0});
    AppendLe(length - 1, 2, &bytes);
    AppendLe(fields_.size(), 2, &bytes);
    for (const auto& s : streams) AppendLe(s.size(), 2, &bytes);
    for (const auto& s : streams) bytes.insert(bytes.end(), s.begin(), s.end());
    bytes.resize(length, 0);
    out->Write(bytes.data(), bytes.size());
  }
}

}  // namespace io_internal
}  // namespace edgefit
