#include <climits>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <lzf.h>

#include "binary_field.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/pcd.h"
#include "read_common.h"
#include "text_parse.h"

namespace edgefit {
namespace {

using io_internal::AtLine;
using io_internal::LineCursor;
using io_internal::ScalarType;

struct PcdField {
  std::string name;
  int size = 4;
  char type = 'F';
  int count = 1;
  ScalarType scalar = ScalarType::kFloat32;
  int offset = 0;  // bytes into a binary record
  int token = 0;   // first token on an ascii line
};

struct PcdHeader {
  std::vector<PcdField> fields;
  int64_t width = -1, height = -1, points = -1;
  double viewpoint[7] = {0, 0, 0, 1, 0, 0, 0};
  std::string data;
  int record_bytes = 0, tokens = 0;
};

bool ToInt(std::string_view s, int64_t* v) {
  const char* p = s.data();
  return io_internal::ParseInt(&p, s.data() + s.size(), v) && p == s.data() + s.size();
}

Status ParseHeader(const std::string& name, LineCursor* cursor, PcdHeader* h) {
  const char *b, *e;
  std::vector<int64_t> sizes, counts;
  std::vector<std::string> types;
  while (h->data.empty()) {
    if (!cursor->Next(&b, &e)) return Status::Error(name + ": no DATA line (empty or truncated header)");
    const auto tokens = io_internal::SplitTokens(b, e);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string key(tokens[0]);
    const std::string where = AtLine(name, cursor->line());
    auto ints = [&](std::vector<int64_t>* out) {
      for (size_t i = 1; i < tokens.size(); ++i) {
        int64_t v;
        if (!ToInt(tokens[i], &v) || v <= 0) return false;
        out->push_back(v);
      }
      return true;
    };
    if (key == "VERSION") continue;
    if (key == "FIELDS") {
      for (size_t i = 1; i < tokens.size(); ++i) h->fields.push_back({std::string(tokens[i])});
    } else if (key == "SIZE") {
      if (!ints(&sizes)) return Status::Error(where + "SIZE needs positive integers");
    } else if (key == "COUNT") {
      if (!ints(&counts)) return Status::Error(where + "COUNT needs positive integers");
    } else if (key == "TYPE") {
      for (size_t i = 1; i < tokens.size(); ++i) types.emplace_back(tokens[i]);
    } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
      std::vector<int64_t> v;
      if (tokens.size() != 2 || !ints(&v)) return Status::Error(where + key + " needs one positive integer");
      (key == "WIDTH" ? h->width : key == "HEIGHT" ? h->height : h->points) = v[0];
    } else if (key == "VIEWPOINT") {
      const char* p = b + (tokens[0].data() + tokens[0].size() - b);
      for (double& v : h->viewpoint) {
        if (!io_internal::ParseReal(&p, e, &v) || !std::isfinite(v)) {
          return Status::Error(where + "VIEWPOINT needs 7 finite numbers tx ty tz qw qx qy qz");
        }
      }
      if (!io_internal::OnlyBlanks(p, e)) return Status::Error(where + "VIEWPOINT needs 7 numbers");
    } else if (key == "DATA") {
      if (tokens.size() != 2) {
        return Status::Error(where + "DATA needs one of ascii, binary, binary_compressed");
      }
      h->data = std::string(tokens[1]);
      if (h->data != "ascii" && h->data != "binary" && h->data != "binary_compressed") {
        return Status::Error(where + "unknown DATA '" + h->data +
                             "' (expected ascii, binary or binary_compressed)");
      }
    } else {
      return Status::Error(where + "unknown PCD header key '" + key + "'");
    }
  }
  const std::string where = AtLine(name, cursor->line());
  const size_t n = h->fields.size();
  if (n == 0) return Status::Error(where + "no FIELDS before DATA");
  if (sizes.size() != n || types.size() != n || (!counts.empty() && counts.size() != n)) {
    return Status::Error(where + "FIELDS, SIZE, TYPE and COUNT disagree in length");
  }
  if (h->width <= 0 || h->height <= 0) return Status::Error(where + "WIDTH and HEIGHT are required");
  if (h->width > INT_MAX || h->height > INT_MAX || h->width * h->height > INT_MAX) {
    return Status::Error(where + "WIDTH x HEIGHT is too large");
  }
  if (h->points >= 0 && h->points != h->width * h->height) {
    return Status::Error(where + "POINTS " + std::to_string(h->points) + " != WIDTH x HEIGHT " +
                         std::to_string(h->width * h->height));
  }
  // A point's record: far below this in any PCD (a 308-float VFH is 1.2 kB);
  // bounded so that SIZE x COUNT can neither overflow nor promise gigabytes.
  constexpr int64_t kMaxRecordBytes = int64_t{1} << 20;
  for (size_t i = 0; i < n; ++i) {
    PcdField& f = h->fields[i];
    const int64_t count = counts.empty() ? 1 : counts[i];
    if (sizes[i] > 8 || count > kMaxRecordBytes ||
        h->record_bytes + sizes[i] * count > kMaxRecordBytes) {
      return Status::Error(where + "field " + f.name + ": SIZE " + std::to_string(sizes[i]) +
                           " x COUNT " + std::to_string(count) +
                           " makes a point record larger than 1 MiB");
    }
    f.size = static_cast<int>(sizes[i]);
    f.count = static_cast<int>(count);
    if (types[i].size() != 1 || !io_internal::PcdScalarType(types[i][0], f.size, &f.scalar)) {
      return Status::Error(where + "unsupported TYPE/SIZE '" + types[i] + "'/" +
                           std::to_string(f.size) + " of field " + f.name);
    }
    f.type = types[i][0];
    f.offset = h->record_bytes;
    f.token = h->tokens;
    h->record_bytes += f.size * f.count;
    h->tokens += f.count;
  }
  return Status::Ok();
}

int FindField(const PcdHeader& h, std::initializer_list<const char*> names) {
  for (size_t i = 0; i < h.fields.size(); ++i) {
    for (const char* n : names) {
      if (h.fields[i].name == n) return static_cast<int>(i);
    }
  }
  return -1;
}

// Packed colour 0x??RRGGBB to RGB.
std::array<uint8_t, 3> Unpack(uint32_t v) {
  return {static_cast<uint8_t>((v >> 16) & 255u), static_cast<uint8_t>((v >> 8) & 255u),
          static_cast<uint8_t>(v & 255u)};
}

// DATA binary_compressed (PCL's pcl::PCDWriter::writeBinaryCompressed):
// uint32 compressed size, uint32 uncompressed size (little endian), then
// LZF-compressed bytes that hold each field's values for every point in
// turn (field by field, not point by point). Sets *records to the points'
// records as DATA binary lays them out.
Status DecompressRecords(const std::string& name, const PcdHeader& h, int64_t points,
                         const char* data, int64_t left, std::string* records) {
  if (left < 8) return Status::Error(name + ": binary_compressed data ends before its two sizes");
  const bool swap = !io_internal::HostIsLittleEndian();
  uint32_t sizes[2];
  for (int i = 0; i < 2; ++i) io_internal::LoadBytes(data + 4 * i, 4, swap, &sizes[i]);
  const int64_t compressed = sizes[0], uncompressed = sizes[1];
  const int64_t expected = points * h.record_bytes;
  if (uncompressed != expected) {
    return Status::Error(name + ": binary_compressed holds " + std::to_string(uncompressed) +
                         " bytes, but " + std::to_string(points) + " points of " +
                         std::to_string(h.record_bytes) + " bytes need " + std::to_string(expected));
  }
  if (compressed > left - 8) {
    return Status::Error(name + ": binary_compressed promises " + std::to_string(compressed) +
                         " compressed bytes but only " + std::to_string(left - 8) +
                         " follow (file truncated?)");
  }
  // LZF grows a byte to at most 88 (a 3-byte reference to 264 bytes): a
  // larger claim is a corrupt header, refused before it is allocated.
  if (uncompressed > 88 * compressed + 32) {
    return Status::Error(name + ": binary_compressed claims " + std::to_string(uncompressed) +
                         " bytes from " + std::to_string(compressed) + " (corrupt sizes)");
  }
  std::string fields(static_cast<size_t>(uncompressed), '\0');
  if (lzf_decompress(data + 8, static_cast<unsigned>(compressed), fields.data(),
                     static_cast<unsigned>(uncompressed)) != static_cast<unsigned>(uncompressed)) {
    return Status::Error(name + ": binary_compressed data does not decompress to " +
                         std::to_string(uncompressed) + " bytes (corrupt LZF stream)");
  }
  records->assign(static_cast<size_t>(expected), '\0');
  const char* block = fields.data();  // this field's values for every point
  for (const PcdField& f : h.fields) {
    const size_t bytes = static_cast<size_t>(f.size) * static_cast<size_t>(f.count);
    for (int64_t p = 0; p < points; ++p) {
      std::memcpy(records->data() + p * h.record_bytes + f.offset,
                  block + p * static_cast<int64_t>(bytes), bytes);
    }
    block += points * static_cast<int64_t>(bytes);
  }
  return Status::Ok();
}

}  // namespace

Status ParsePcd(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans) {
  LineCursor cursor(content.data(), content.data() + content.size());
  PcdHeader h;
  EDGEFIT_RETURN_IF_ERROR(ParseHeader(name, &cursor, &h));
  const int ix = FindField(h, {"x"}), iy = FindField(h, {"y"}), iz = FindField(h, {"z"});
  const int ii = FindField(h, {"intensity"}), ic = FindField(h, {"rgb", "rgba"});
  if (ix < 0 || iy < 0 || iz < 0) return Status::Error(name + ": FIELDS must include x y z");
  if (ic >= 0 && h.fields[static_cast<size_t>(ic)].size != 4) {
    return Status::Error(name + ": field " + h.fields[static_cast<size_t>(ic)].name + " must have SIZE 4");
  }
  const int64_t n = h.width * h.height;
  const int64_t left = cursor.end() - cursor.position();
  std::string decompressed;  // binary_compressed: the records, laid out as binary
  if (h.data == "binary_compressed") {
    EDGEFIT_RETURN_IF_ERROR(DecompressRecords(name, h, n, cursor.position(), left, &decompressed));
  } else if (h.data == "binary" ? n * h.record_bytes > left : n > (left + 1) / 2) {
    return Status::Error(name + ": header promises " + std::to_string(n) + " points but only " +
                         std::to_string(left) + " bytes of data follow (file truncated?)");
  }
  const bool organized = h.height > 1;
  OrganizedScan scan = organized ? OrganizedScan(static_cast<int>(h.height), static_cast<int>(h.width))
                                 : OrganizedScan(1, static_cast<int>(n));
  scan.set_organized(organized);
  scan.set_file_order(OrganizedScan::FileOrder::kRowMajor);
  if (ic >= 0) scan.EnableColor();
  const double* vp = h.viewpoint;
  const Eigen::Quaterniond q(vp[3], vp[4], vp[5], vp[6]);
  if (q.norm() < 1e-9) return Status::Error(name + ": VIEWPOINT quaternion is zero");
  Pose T_world_scanner = Pose::Identity();
  T_world_scanner.linear() = q.normalized().toRotationMatrix();
  T_world_scanner.translation() = Eigen::Vector3d(vp[0], vp[1], vp[2]);
  scan.set_T_world_scanner(T_world_scanner);

  std::vector<double> values(static_cast<size_t>(h.tokens));
  uint32_t packed = 0;
  const bool binary = h.data != "ascii";
  const bool swap = !io_internal::HostIsLittleEndian();
  const char* data = h.data == "binary_compressed" ? decompressed.data() : cursor.position();
  for (int64_t f = 0; f < n; ++f) {
    auto where = [&]() {
      return binary ? name + ": point " + std::to_string(f + 1) + ": " : AtLine(name, cursor.line());
    };
    if (binary) {
      const char* record = data + f * h.record_bytes;
      for (const PcdField& field : h.fields) {
        values[static_cast<size_t>(field.token)] = io_internal::DecodeScalar(record + field.offset, field.scalar, swap);
      }
      if (ic >= 0) io_internal::LoadBytes(record + h.fields[static_cast<size_t>(ic)].offset, 4, swap, &packed);
    } else {
      const char *b, *e;
      if (!cursor.Next(&b, &e)) {
        return Status::Error(AtLine(name, cursor.line() + 1) + "file ends after " + std::to_string(f) +
                             " of " + std::to_string(n) + " points (truncated?)");
      }
      const char* p = b;
      for (int t = 0; t < h.tokens; ++t) {
        const char* token = p;
        bool ok = io_internal::ParseReal(&p, e, &values[static_cast<size_t>(t)]);
        if (ic >= 0 && t == h.fields[static_cast<size_t>(ic)].token) {
          // Colour: PCL prints the packed bits as an unsigned integer; a
          // float spelling of the same bits is accepted too.
          p = token;
          ok = io_internal::ParseInt(&p, e, &packed);
          float as_float;
          if (!ok && (p = token, io_internal::ParseReal(&p, e, &as_float))) {
            std::memcpy(&packed, &as_float, 4);
            ok = true;
          }
        }
        if (!ok) {
          return Status::Error(where() + "expected " + std::to_string(h.tokens) + " numbers, got '" +
                               io_internal::Excerpt(b, e) + "'");
        }
      }
      if (!io_internal::OnlyBlanks(p, e)) {
        return Status::Error(where() + "more than " + std::to_string(h.tokens) + " numbers on a point line");
      }
    }
    const Eigen::Vector3d p(values[static_cast<size_t>(h.fields[ix].token)],
                            values[static_cast<size_t>(h.fields[iy].token)],
                            values[static_cast<size_t>(h.fields[iz].token)]);
    const size_t cell = organized ? scan.Index(static_cast<int>(f / h.width), static_cast<int>(f % h.width))
                                  : static_cast<size_t>(f);
    if (ic >= 0) scan.SetColor(cell, Unpack(packed));
    if (std::isnan(p.x()) || std::isnan(p.y()) || std::isnan(p.z())) continue;  // missing
    const double intensity = ii >= 0 ? values[static_cast<size_t>(h.fields[ii].token)] : 0.0;
    if (!p.allFinite() || !std::isfinite(intensity)) {
      return Status::Error(where() + "infinite coordinate or intensity");
    }
    scan.SetPoint(cell, p.cast<float>(), static_cast<float>(intensity));
  }
  EDGEFIT_RETURN_IF_ERROR(io_internal::FinishScan(name, options, &scan));
  scans->scans.push_back(std::move(scan));
  scans->sources.push_back(name);
  return Status::Ok();
}

Status ReadPcd(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  std::string content;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &content));
  return ParsePcd(content, path, options, scans);
}

}  // namespace edgefit
