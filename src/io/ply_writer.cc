#include <charconv>
#include <ostream>
#include <string>

#include "binary_field.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/ply.h"

namespace edgefit {

Status WritePly(const std::string& path, const ScanSet& scans, const WriteOptions& options) {
  if (options.binary && !io_internal::HostIsLittleEndian()) {
    return Status::Error(path + ": binary PLY output needs a little-endian host");
  }
  size_t n = 0;
  bool color = !scans.scans.empty();
  for (const OrganizedScan& scan : scans.scans) {
    n += scan.CountValid();
    color &= scan.has_color();
  }
  std::string header = std::string("ply\nformat ") + (options.binary ? "binary_little_endian" : "ascii") +
                       " 1.0\ncomment edgefit: valid scan points in world coordinates [m]\nelement vertex " +
                       std::to_string(n) +
                       "\nproperty float x\nproperty float y\nproperty float z\nproperty float intensity\n";
  if (color) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  header += "end_header\n";
  return WriteFileAtomically(path, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::string body;
    char buf[32];
    for (const OrganizedScan& scan : scans.scans) {
      for (size_t i = 0; i < scan.size(); ++i) {
        if (!scan.IsValid(i)) continue;
        const Eigen::Vector3f p = scan.PointWorld(i).cast<float>();
        const float v[4] = {p.x(), p.y(), p.z(), scan.intensity(i)};
        if (options.binary) {
          body.append(reinterpret_cast<const char*>(v), sizeof(v));
          if (color) body.append(reinterpret_cast<const char*>(scan.color(i).data()), 3);
        } else {
          for (int k = 0; k < 4; ++k) {
            if (k > 0) body.push_back(' ');
            body.append(buf, std::to_chars(buf, buf + sizeof(buf), v[k]).ptr);
          }
          if (color) {
            for (uint8_t c : scan.color(i)) {
              body.push_back(' ');
              body.append(buf, std::to_chars(buf, buf + sizeof(buf), static_cast<int>(c)).ptr);
            }
          }
          body.push_back('\n');
        }
        if (body.size() > (1u << 20)) {
          out.write(body.data(), static_cast<std::streamsize>(body.size()));
          body.clear();
        }
      }
    }
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    return Status::Ok();
  });
}

}  // namespace edgefit
