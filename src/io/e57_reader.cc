#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "e57_pages.h"
#include "e57_records.h"
#include "e57_xml.h"
#include "edgefit/core/little_endian.h"
#include "edgefit/io/e57.h"
#include "read_common.h"

namespace edgefit {
namespace io_internal {
namespace {

constexpr size_t kHeaderBytes = 48;
// Records decoded per block.
constexpr size_t kBlockRecords = 65536;
// An organized grid may hold this many cells per record (files that write
// only valid cells), plus a constant for small scans; more means corrupt
// index bounds, not a scan.
constexpr uint64_t kMaxCellsPerRecord = 16;
constexpr uint64_t kMaxExtraCells = uint64_t{1} << 20;

// Which prototype fields hold what; -1 when absent.
struct FieldMap {
  int coordinate[3] = {-1, -1, -1};  // x y z, or range azimuth elevation
  bool spherical = false;
  int invalid = -1;
  int row = -1, col = -1;
  int intensity = -1;
  int color[3] = {-1, -1, -1};
  int return_index = -1;

  bool organized() const { return row >= 0 && col >= 0; }
};

int FieldIndex(const E57Points& points, const char* name) {
  for (size_t f = 0; f < points.fields.size(); ++f) {
    if (points.fields[f].name == name) return static_cast<int>(f);
  }
  return -1;
}

Status MapFields(const E57Scan& scan, const std::string& where, FieldMap* map) {
  const E57Points& p = scan.points;
  const char* cartesian[3] = {"cartesianX", "cartesianY", "cartesianZ"};
  const char* spherical[3] = {"sphericalRange", "sphericalAzimuth", "sphericalElevation"};
  for (int k = 0; k < 3; ++k) map->coordinate[k] = FieldIndex(p, cartesian[k]);
  map->invalid = FieldIndex(p, "cartesianInvalidState");
  if (map->coordinate[0] < 0 || map->coordinate[1] < 0 || map->coordinate[2] < 0) {
    for (int k = 0; k < 3; ++k) map->coordinate[k] = FieldIndex(p, spherical[k]);
    map->spherical = true;
    map->invalid = FieldIndex(p, "sphericalInvalidState");
    if (map->coordinate[0] < 0 || map->coordinate[1] < 0 || map->coordinate[2] < 0) {
      return Status::Error(where + ": the points have neither cartesianX/Y/Z nor "
                           "sphericalRange/Azimuth/Elevation");
    }
  }
  map->row = FieldIndex(p, "rowIndex");
  map->col = FieldIndex(p, "columnIndex");
  map->intensity = FieldIndex(p, "intensity");
  const char* colours[3] = {"colorRed", "colorGreen", "colorBlue"};
  for (int k = 0; k < 3; ++k) map->color[k] = FieldIndex(p, colours[k]);
  if (map->color[0] < 0 || map->color[1] < 0 || map->color[2] < 0) map->color[0] = -1;
  map->return_index = FieldIndex(p, "returnIndex");
  return Status::Ok();
}

// Calls `visit(values, count)` for each block of decoded records.
template <typename Visit>
Status ForEachBlock(E57PageReader* file, const E57Scan& scan, const std::string& where, Visit visit) {
  E57RecordReader reader(file, scan.points, where);
  EDGEFIT_RETURN_IF_ERROR(reader.Start());
  std::vector<double> values;
  uint64_t first = 0;
  while (true) {
    size_t count = 0;
    EDGEFIT_RETURN_IF_ERROR(reader.Next(kBlockRecords, &values, &count));
    if (count == 0) return Status::Ok();
    EDGEFIT_RETURN_IF_ERROR(visit(values.data(), count, first));
    first += count;
  }
}

// The grid of an organized scan: its indexBounds, or one pass over the
// records' indices when the file has none.
Status GridBounds(E57PageReader* file, const E57Scan& scan, const FieldMap& map,
                  const std::string& where, int64_t bounds[4]) {
  if (scan.has_index_bounds) {
    bounds[0] = scan.row_min, bounds[1] = scan.row_max, bounds[2] = scan.col_min, bounds[3] = scan.col_max;
  } else {
    bounds[0] = bounds[2] = std::numeric_limits<int64_t>::max();
    bounds[1] = bounds[3] = std::numeric_limits<int64_t>::min();
    EDGEFIT_RETURN_IF_ERROR(ForEachBlock(file, scan, where, [&](const double* v, size_t n, uint64_t) {
      for (size_t r = 0; r < n; ++r) {
        const auto row = static_cast<int64_t>(v[static_cast<size_t>(map.row) * n + r]);
        const auto col = static_cast<int64_t>(v[static_cast<size_t>(map.col) * n + r]);
        bounds[0] = std::min(bounds[0], row), bounds[1] = std::max(bounds[1], row);
        bounds[2] = std::min(bounds[2], col), bounds[3] = std::max(bounds[3], col);
      }
      return Status::Ok();
    }));
  }
  const double rows = static_cast<double>(bounds[1]) - static_cast<double>(bounds[0]) + 1.0;
  const double cols = static_cast<double>(bounds[3]) - static_cast<double>(bounds[2]) + 1.0;
  const double records = static_cast<double>(scan.points.record_count);
  if (rows < 1 || cols < 1 || rows > std::numeric_limits<int>::max() || cols > std::numeric_limits<int>::max() ||
      rows * cols > records * kMaxCellsPerRecord + kMaxExtraCells) {
    return Status::Error(where + ": index bounds rows " + std::to_string(bounds[0]) + ".." +
                         std::to_string(bounds[1]) + ", columns " + std::to_string(bounds[2]) + ".." +
                         std::to_string(bounds[3]) + " do not fit " +
                         std::to_string(scan.points.record_count) + " records");
  }
  return Status::Ok();
}

// The colour range a stored value maps from: colorLimits, else the
// prototype's bounds of an integer field, else 0..255.
void ColourRange(const E57Scan& scan, const FieldMap& map, double lo[3], double hi[3]) {
  for (int k = 0; k < 3; ++k) {
    const E57Field& f = scan.points.fields[static_cast<size_t>(map.color[k])];
    const bool integer = f.type != E57Field::Type::kFloat;
    lo[k] = scan.has_color_limits ? scan.color_min[k] : integer ? static_cast<double>(f.minimum) : 0.0;
    hi[k] = scan.has_color_limits ? scan.color_max[k] : integer ? static_cast<double>(f.maximum) : 255.0;
    if (!(hi[k] > lo[k])) lo[k] = 0.0, hi[k] = 255.0;
  }
}

Status ReadScan(E57PageReader* file, const E57Scan& e, const std::string& where, OrganizedScan* scan) {
  FieldMap map;
  EDGEFIT_RETURN_IF_ERROR(MapFields(e, where, &map));
  uint64_t bits = 0;
  for (const E57Field& f : e.points.fields) bits += static_cast<uint64_t>(f.Bits());
  if (e.points.record_count > file->logical_size() * 8 / std::max<uint64_t>(bits, 1)) {
    return Status::Error(where + ": recordCount " + std::to_string(e.points.record_count) +
                         " is more than the file can hold");
  }
  int64_t bounds[4] = {0, 0, 0, 0};
  if (map.organized()) {
    EDGEFIT_RETURN_IF_ERROR(GridBounds(file, e, map, where, bounds));
    *scan = OrganizedScan(static_cast<int>(bounds[1] - bounds[0] + 1), static_cast<int>(bounds[3] - bounds[2] + 1));
  } else {
    if (e.points.record_count > static_cast<uint64_t>(std::numeric_limits<int>::max())) {
      return Status::Error(where + ": more than 2^31 unorganized points in one scan");
    }
    *scan = OrganizedScan(1, static_cast<int>(e.points.record_count));
    scan->set_organized(false);
  }
  scan->set_T_world_scanner(e.T_world_scanner);
  double lo[3] = {0, 0, 0}, hi[3] = {255, 255, 255};
  if (map.color[0] >= 0) {
    scan->EnableColor();
    ColourRange(e, map, lo, hi);
  }
  return ForEachBlock(file, e, where, [&](const double* v, size_t n, uint64_t first) {
    const auto field = [&](int f, size_t r) { return v[static_cast<size_t>(f) * n + r]; };
    for (size_t r = 0; r < n; ++r) {
      if (map.organized() && map.return_index >= 0 && field(map.return_index, r) != 0.0) continue;
      if (map.invalid >= 0 && field(map.invalid, r) != 0.0) continue;
      size_t cell = static_cast<size_t>(first + r);
      if (map.organized()) {
        const double row = field(map.row, r) - static_cast<double>(bounds[0]);
        const double col = field(map.col, r) - static_cast<double>(bounds[2]);
        if (!(row >= 0 && row < scan->rows() && col >= 0 && col < scan->cols())) {
          return Status::Error(where + ": record " + std::to_string(first + r) + " has rowIndex " +
                               std::to_string(static_cast<int64_t>(field(map.row, r))) + ", columnIndex " +
                               std::to_string(static_cast<int64_t>(field(map.col, r))) +
                               " outside the index bounds");
        }
        cell = scan->Index(static_cast<int>(row), static_cast<int>(col));
      }
      Eigen::Vector3d p(field(map.coordinate[0], r), field(map.coordinate[1], r), field(map.coordinate[2], r));
      if (map.spherical) {
        const double range = p[0], azimuth = p[1], elevation = p[2];
        p = range * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      }
      if (!p.allFinite()) {
        return Status::Error(where + ": record " + std::to_string(first + r) + " has a non-finite coordinate");
      }
      const float intensity = map.intensity >= 0 ? static_cast<float>(field(map.intensity, r)) : 0.0f;
      scan->SetPoint(cell, p.cast<float>(), intensity);
      if (map.color[0] >= 0) {
        std::array<uint8_t, 3> rgb;
        for (int k = 0; k < 3; ++k) {
          const double c = (field(map.color[k], r) - lo[k]) / (hi[k] - lo[k]) * 255.0;
          rgb[static_cast<size_t>(k)] = static_cast<uint8_t>(std::lround(std::clamp(c, 0.0, 255.0)));
        }
        scan->SetColor(cell, rgb);
      }
    }
    return Status::Ok();
  });
}

Status ReadFile(E57PageReader* file, const ReadOptions& options, ScanSet* scans) {
  const std::string& name = file->name();
  EDGEFIT_RETURN_IF_ERROR(file->CheckSize());
  uint8_t h[kHeaderBytes];
  EDGEFIT_RETURN_IF_ERROR(file->Read(0, kHeaderBytes, h));
  if (std::memcmp(h, "ASTM-E57", 8) != 0) return Status::Error(name + ": not an E57 file (no ASTM-E57 signature)");
  const uint64_t major = LoadUintLE(h + 8, 4);
  const uint64_t length = LoadUintLE(h + 16, 8), xml_offset = LoadUintLE(h + 24, 8), xml_length = LoadUintLE(h + 32, 8), page = LoadUintLE(h + 40, 8);
  if (major != 1) return Status::Error(name + ": E57 version " + std::to_string(major) + " (edgefit reads version 1)");
  if (page != kE57PageBytes) return Status::Error(name + ": page size " + std::to_string(page) + " (the standard's is 1024)");
  if (length != file->physical_size()) {
    return Status::Error(name + ": the header says " + std::to_string(length) + " bytes, the file has " +
                         std::to_string(file->physical_size()) + " (truncated?)");
  }
  if (xml_offset % kE57PageBytes >= kE57PageDataBytes || E57Logical(xml_offset) > file->logical_size() ||
      xml_length > file->logical_size() - E57Logical(xml_offset) || xml_length == 0) {
    return Status::Error(name + ": the XML section (offset " + std::to_string(xml_offset) + ", " +
                         std::to_string(xml_length) + " bytes) does not fit the file");
  }
  std::string xml(static_cast<size_t>(xml_length), '\0');
  EDGEFIT_RETURN_IF_ERROR(file->Read(E57Logical(xml_offset), xml.size(), xml.data()));
  std::vector<E57Scan> described;
  EDGEFIT_RETURN_IF_ERROR(ParseE57Xml(xml, name, &described));
  if (described.empty()) return Status::Error(name + ": no 3D data (/data3D is empty)");
  ScanSet parsed;
  for (size_t i = 0; i < described.size(); ++i) {
    const std::string where = name + ": /data3D/" + std::to_string(i) +
                              (described[i].name.empty() ? "" : " '" + described[i].name + "'");
    OrganizedScan scan;
    EDGEFIT_RETURN_IF_ERROR(ReadScan(file, described[i], where, &scan));
    EDGEFIT_RETURN_IF_ERROR(FinishScan(where, options, &scan));
    parsed.scans.push_back(std::move(scan));
    parsed.sources.push_back(name);
  }
  for (size_t i = 0; i < parsed.scans.size(); ++i) {
    scans->scans.push_back(std::move(parsed.scans[i]));
    scans->sources.push_back(std::move(parsed.sources[i]));
  }
  return Status::Ok();
}

}  // namespace
}  // namespace io_internal

Status ParseE57(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans) {
  io_internal::E57PageReader file(content, name);
  return io_internal::ReadFile(&file, options, scans);
}

Status ReadE57(const std::string& path, const ReadOptions& options, ScanSet* scans) {
  io_internal::E57PageReader file({}, path);
  EDGEFIT_RETURN_IF_ERROR(file.Open(path));
  return io_internal::ReadFile(&file, options, scans);
}

}  // namespace edgefit
