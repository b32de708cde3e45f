// Private: E57's XML section (ASTM E2807, 8): what edgefit reads from it and
// writes to it. Each /data3D child is one scan: its pose, its index bounds,
// its colour limits and the prototype of its points, the CompressedVector
// whose records are decoded by e57_records.h.
#ifndef EDGEFIT_SRC_IO_E57_XML_H_
#define EDGEFIT_SRC_IO_E57_XML_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"

namespace edgefit {
namespace io_internal {

// One terminal field of a points prototype, in the order of the bytestreams.
struct E57Field {
  enum class Type { kInteger, kScaledInteger, kFloat };
  std::string name;  // path below the prototype, e.g. "cartesianX"
  Type type = Type::kFloat;
  bool single = false;  // Float: precision="single"
  int64_t minimum = 0;  // Integer, ScaledInteger: raw bounds
  int64_t maximum = 0;
  double scale = 1.0;  // ScaledInteger: value = raw * scale + offset
  double offset = 0.0;

  // Bits per value in the bitpack codec: 32 or 64 for Float, otherwise
  // ceil(log2(maximum - minimum + 1)) (0 for a constant).
  int Bits() const;
};

struct E57Points {
  uint64_t file_offset = 0;  // physical offset of the section header
  uint64_t record_count = 0;
  std::vector<E57Field> fields;
};

struct E57Scan {
  std::string name;
  std::string guid;
  Pose T_world_scanner = Pose::Identity();  // /pose, identity when absent
  bool has_index_bounds = false;
  int64_t row_min = 0, row_max = 0, col_min = 0, col_max = 0;
  bool has_color_limits = false;
  double color_min[3] = {0, 0, 0};
  double color_max[3] = {255, 255, 255};
  bool has_intensity_limits = false;
  double intensity_min = 0.0, intensity_max = 1.0;
  E57Points points;
};

// Parses the XML section; `name` prefixes messages. Fails on XML syntax, a
// root that is not e57Root, a data3D child without points, and prototype
// fields of a type the bitpack codec cannot hold (String, Blob, Vector).
Status ParseE57Xml(std::string_view xml, const std::string& name, std::vector<E57Scan>* scans);

// The XML section for `scans` (guids and offsets filled in by the caller).
std::string E57Xml(const std::vector<E57Scan>& scans, const std::string& file_guid);

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_E57_XML_H_
