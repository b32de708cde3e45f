#include <charconv>
#include <cmath>
#include <cstring>
#include <ostream>
#include <string>

#include "binary_field.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/pcd.h"
#include "number_text.h"

namespace edgefit {
namespace {

using io_internal::AppendNumber;

uint32_t Pack(const std::array<uint8_t, 3>& rgb) {
  return (static_cast<uint32_t>(rgb[0]) << 16) | (static_cast<uint32_t>(rgb[1]) << 8) | rgb[2];
}

}  // namespace

Status WritePcd(const std::string& path, const OrganizedScan& scan, const WriteOptions& options) {
  if (scan.size() == 0) return Status::Error(path + ": no points to write");
  if (options.binary && !io_internal::HostIsLittleEndian()) {
    return Status::Error(path + ": binary PCD output needs a little-endian host");
  }
  const bool color = scan.has_color();
  // An unorganized cloud is one row of N points.
  const int rows = scan.organized() ? scan.rows() : 1;
  const int cols = scan.organized() ? scan.cols() : static_cast<int>(scan.size());
  const Eigen::Quaterniond q(scan.T_world_scanner().linear());
  const Eigen::Vector3d t = scan.T_world_scanner().translation();
  std::string header = "# .PCD v0.7 - Point Cloud Data file format (edgefit)\nVERSION 0.7\n";
  header += color ? "FIELDS x y z intensity rgb\nSIZE 4 4 4 4 4\nTYPE F F F F U\nCOUNT 1 1 1 1 1\n"
                  : "FIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n";
  header += "WIDTH " + std::to_string(cols) + "\nHEIGHT " + std::to_string(rows) + "\nVIEWPOINT";
  for (double v : {t.x(), t.y(), t.z(), q.w(), q.x(), q.y(), q.z()}) {
    header.push_back(' ');
    AppendNumber(v, &header);
  }
  header += "\nPOINTS " + std::to_string(scan.size()) + "\nDATA " +
            (options.binary ? "binary" : "ascii") + "\n";
  return WriteFileAtomically(path, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::string body;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const size_t i = scan.organized() ? scan.Index(r, c) : static_cast<size_t>(c);
        const Eigen::Vector3f& p = scan.point_scanner(i);
        const float v[4] = {p.x(), p.y(), p.z(), scan.intensity(i)};
        const uint32_t rgb = color ? Pack(scan.color(i)) : 0u;
        if (options.binary) {
          body.append(reinterpret_cast<const char*>(v), sizeof(v));
          if (color) body.append(reinterpret_cast<const char*>(&rgb), 4);
        } else {
          for (int k = 0; k < 4; ++k) {
            AppendNumber(v[k], &body);
            body.push_back(k < 3 || color ? ' ' : '\n');
          }
          if (color) {
            AppendNumber(rgb, &body);
            body.push_back('\n');
          }
        }
      }
      if (body.size() > (1u << 20)) {
        out.write(body.data(), static_cast<std::streamsize>(body.size()));
        body.clear();
      }
    }
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    return Status::Ok();
  });
}

}  // namespace edgefit
