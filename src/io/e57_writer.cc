#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "e57_pages.h"
#include "e57_records.h"
#include "e57_xml.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/core/little_endian.h"
#include "edgefit/io/e57.h"

namespace edgefit {
namespace io_internal {
namespace {

// FNV-1a, for guids that depend on the content only (deterministic output).
class Fnv {
 public:
  void Add(const void* data, size_t n) {
    const auto* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ull;
  }
  std::string Guid(uint64_t salt) const {
    char text[48];
    const uint64_t h = hash_ ^ (salt * 0x9E3779B97F4A7C15ull);
    std::snprintf(text, sizeof(text), "{edgefit-%016" PRIx64 "}", h);
    return text;
  }

 private:
  uint64_t hash_ = 1469598103934665603ull;
};

E57Field FloatField(const char* name) {
  E57Field f;
  f.name = name;
  f.type = E57Field::Type::kFloat;
  f.single = true;
  return f;
}

E57Field IntegerField(const char* name, int64_t minimum, int64_t maximum) {
  E57Field f;
  f.name = name;
  f.type = E57Field::Type::kInteger;
  f.minimum = minimum;
  f.maximum = maximum;
  return f;
}

// The description of `scan` as E57 writes it (file offset filled in later).
E57Scan Describe(const OrganizedScan& scan, size_t index, Fnv* fnv) {
  E57Scan d;
  d.name = "scan " + std::to_string(index + 1);
  d.T_world_scanner = scan.T_world_scanner();
  auto& fields = d.points.fields;
  for (const char* name : {"cartesianX", "cartesianY", "cartesianZ", "intensity"}) fields.push_back(FloatField(name));
  if (scan.has_color()) {
    d.has_color_limits = true;
    for (const char* name : {"colorRed", "colorGreen", "colorBlue"}) fields.push_back(IntegerField(name, 0, 255));
  }
  if (scan.organized()) {
    d.has_index_bounds = true;
    d.row_max = scan.rows() - 1;
    d.col_max = scan.cols() - 1;
    fields.push_back(IntegerField("rowIndex", 0, d.row_max));
    fields.push_back(IntegerField("columnIndex", 0, d.col_max));
    fields.push_back(IntegerField("cartesianInvalidState", 0, 2));
  }
  d.points.record_count = scan.organized() ? scan.size() : scan.CountValid();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (!scan.IsValid(i)) continue;
    lo = std::min<double>(lo, scan.intensity(i));
    hi = std::max<double>(hi, scan.intensity(i));
  }
  d.has_intensity_limits = lo <= hi;
  d.intensity_min = lo;
  d.intensity_max = hi;
  const int sizes[2] = {scan.rows(), scan.cols()};
  fnv->Add(sizes, sizeof(sizes));
  fnv->Add(scan.T_world_scanner().matrix().data(), 16 * sizeof(double));
  for (size_t i = 0; i < scan.size(); i += 997) fnv->Add(scan.point_scanner(i).data(), 3 * sizeof(float));
  d.guid = fnv->Guid(index + 1);
  return d;
}

// Supplies the records of `scan` in cell order (organized: every cell;
// unorganized: the valid cells), field-major, in Describe()'s field order.
class RecordSource {
 public:
  explicit RecordSource(const OrganizedScan& scan) : scan_(scan) {}
  void operator()(uint64_t /*first*/, size_t count, std::vector<double>* values) {
    const size_t fields = 4 + (scan_.has_color() ? 3 : 0) + (scan_.organized() ? 3 : 0);
    values->assign(fields * count, 0.0);
    double* v = values->data();
    for (size_t r = 0; r < count; ++r, ++next_) {
      if (!scan_.organized()) {
        while (!scan_.IsValid(next_)) ++next_;
      }
      const bool valid = scan_.IsValid(next_);
      size_t f = 0;
      if (valid) {
        const Eigen::Vector3f& p = scan_.point_scanner(next_);
        for (int k = 0; k < 3; ++k) v[(f + static_cast<size_t>(k)) * count + r] = p[k];
        v[(f + 3) * count + r] = scan_.intensity(next_);
      }
      f += 4;
      if (scan_.has_color()) {
        for (size_t k = 0; k < 3; ++k) v[(f + k) * count + r] = valid ? scan_.color(next_)[k] : 0;
        f += 3;
      }
      if (scan_.organized()) {
        v[f * count + r] = scan_.RowOf(next_);
        v[(f + 1) * count + r] = scan_.ColOf(next_);
        v[(f + 2) * count + r] = valid ? 0 : 2;
      }
    }
  }

 private:
  const OrganizedScan& scan_;
  size_t next_ = 0;
};

}  // namespace
}  // namespace io_internal

Status WriteE57(const std::string& path, const ScanSet& scans) {
  using namespace io_internal;
  if (scans.scans.empty()) return Status::Error(path + ": no scans to write");
  Fnv fnv;
  std::vector<E57Scan> described;
  uint64_t logical = 48;  // after the file header
  for (size_t i = 0; i < scans.scans.size(); ++i) {
    described.push_back(Describe(scans.scans[i], i, &fnv));
    E57Scan& d = described.back();
    d.points.file_offset = E57Physical(logical);
    logical += E57RecordWriter(d.points.fields).SectionBytes(d.points.record_count);
  }
  const std::string xml = E57Xml(described, fnv.Guid(0));
  const uint64_t xml_offset = E57Physical(logical);
  const uint64_t end = logical + xml.size();
  const uint64_t length = (end + kE57PageDataBytes - 1) / kE57PageDataBytes * kE57PageBytes;
  uint8_t header[48] = {};
  std::memcpy(header, "ASTM-E57", 8);
  StoreUintLE(1, 4, header + 8);  // version 1.0
  StoreUintLE(length, 8, header + 16);
  StoreUintLE(xml_offset, 8, header + 24);
  StoreUintLE(xml.size(), 8, header + 32);
  StoreUintLE(kE57PageBytes, 8, header + 40);
  return WriteFileAtomically(path, [&](std::ostream& out) {
    E57PageWriter pages(&out);
    pages.Write(header, sizeof(header));
    for (size_t i = 0; i < scans.scans.size(); ++i) {
      RecordSource source(scans.scans[i]);
      E57RecordWriter(described[i].points.fields)
          .Write(described[i].points.record_count, std::ref(source), &pages);
    }
    pages.Write(xml.data(), xml.size());
    pages.Finish();
    return Status::Ok();
  });
}

}  // namespace edgefit
