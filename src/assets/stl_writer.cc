#include "edgefit/assets/stl_writer.h"

#include <cstdint>
#include <cstring>
#include <ostream>

#include "edgefit/core/atomic_file.h"
#include "edgefit/core/little_endian.h"

namespace edgefit {
std::string EncodeBinaryStl(const TriangleMesh& mesh, const std::string& solid_name) {
  constexpr size_t kHeaderBytes = 80;
  std::string out;
  out.reserve(kHeaderBytes + 4 + 50 * mesh.triangles.size());
  std::string header = "edgefit procedural mesh: " + solid_name;
  header.resize(kHeaderBytes, '\0');
  out += header;
  AppendUint32LE(static_cast<uint32_t>(mesh.triangles.size()), &out);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    // The corners as float32, as a reader will see them. Each goes through a
    // volatile so the normal below really uses the rounded values: GCC 12 at
    // -O3 was observed to fold (double)(float)x back to x here, which made
    // Release and Debug builds write different normals.
    float corners[3][3];
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) {
        volatile float rounded = static_cast<float>(mesh.vertices[t[k]][i]);
        corners[k][i] = rounded;
      }
    }
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) p[k] = Eigen::Vector3d(corners[k][0], corners[k][1], corners[k][2]);
    Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double norm = n.norm();
    n = norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) AppendFloatLE(static_cast<float>(n[i]), &out);
    for (const float* corner : corners) {
      for (int i = 0; i < 3; ++i) AppendFloatLE(corner[i], &out);
    }
    out.push_back('\0');  // Attribute byte count: 0.
    out.push_back('\0');
  }
  return out;
}

Status WriteBinaryStl(const std::string& path, const TriangleMesh& mesh,
                      const std::string& solid_name) {
  const std::string bytes = EncodeBinaryStl(mesh, solid_name);
  return WriteFileAtomically(path, [&bytes](std::ostream& os) {
    os.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return Status::Ok();
  });
}

}  // namespace edgefit
