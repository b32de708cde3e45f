#include <ostream>
#include <string>

#include "edgefit/core/atomic_file.h"
#include "edgefit/io/ptx.h"
#include "number_text.h"

namespace edgefit {
namespace {

using io_internal::AppendNumber;

void AppendRow(std::initializer_list<double> values, std::string* out) {
  bool first = true;
  for (double v : values) {
    if (!first) out->push_back(' ');
    AppendNumber(v, out);
    first = false;
  }
  out->push_back('\n');
}

Status WriteScan(const OrganizedScan& scan, std::ostream& out) {
  const bool row_major = scan.file_order() == OrganizedScan::FileOrder::kRowMajor;
  std::string text;
  // Line 2 is the run length in the file: rows for column-major files.
  text += std::to_string(row_major ? scan.rows() : scan.cols()) + "\n";
  text += std::to_string(row_major ? scan.cols() : scan.rows()) + "\n";
  const Eigen::Matrix3d R = scan.T_world_scanner().linear();
  const Eigen::Vector3d t = scan.T_world_scanner().translation();
  AppendRow({t.x(), t.y(), t.z()}, &text);
  for (int c = 0; c < 3; ++c) AppendRow({R(0, c), R(1, c), R(2, c)}, &text);
  for (int c = 0; c < 3; ++c) AppendRow({R(0, c), R(1, c), R(2, c), 0.0}, &text);
  AppendRow({t.x(), t.y(), t.z(), 1.0}, &text);
  constexpr size_t kFlushBytes = 1 << 20;
  text.reserve(kFlushBytes + 256);
  for (size_t f = 0; f < scan.size(); ++f) {
    // Cell of file position f (inverse of OrganizedScan::FileIndex).
    const size_t i = row_major ? scan.Index(static_cast<int>(f / static_cast<size_t>(scan.cols())),
                                            static_cast<int>(f % static_cast<size_t>(scan.cols())))
                               : f;
    if (scan.IsValid(i)) {
      const Eigen::Vector3f& p = scan.point_scanner(i);
      AppendNumber(p.x(), &text);
      text.push_back(' ');
      AppendNumber(p.y(), &text);
      text.push_back(' ');
      AppendNumber(p.z(), &text);
      text.push_back(' ');
      AppendNumber(scan.intensity(i), &text);
    } else {
      text += "0 0 0 0";
    }
    if (scan.has_color()) {
      for (uint8_t c : scan.color(i)) {
        text.push_back(' ');
        AppendNumber(static_cast<int>(c), &text);
      }
    }
    text.push_back('\n');
    if (text.size() >= kFlushBytes) {
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  return Status::Ok();
}

}  // namespace

Status WritePtx(const std::string& path, const ScanSet& scans) {
  if (scans.scans.empty()) return Status::Error(path + ": no scans to write");
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    if (!scans.scans[s].organized() || scans.scans[s].size() == 0) {
      return Status::Error(path + ": scan " + std::to_string(s + 1) +
                           " is not an organized grid; PTX holds organized scans only");
    }
  }
  return WriteFileAtomically(path, [&scans](std::ostream& out) {
    for (const OrganizedScan& scan : scans.scans) EDGEFIT_RETURN_IF_ERROR(WriteScan(scan, out));
    return Status::Ok();
  });
}

}  // namespace edgefit
