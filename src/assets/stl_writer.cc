#include "edgefit/assets/stl_writer.h"

#include <cstdint>
#include <cstring>
#include <ostream>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

void AppendUint32(uint32_t value, std::string* out) {
  for (int byte = 0; byte < 4; ++byte) out->push_back(static_cast<char>((value >> (8 * byte)) & 0xff));
}

void AppendFloat(float value, std::string* out) {
  uint32_t bits = 0;
  static_assert(sizeof(bits) == sizeof(value), "float must be 32-bit");
  std::memcpy(&bits, &value, sizeof(bits));
  AppendUint32(bits, out);  // Little-endian IEEE 754 whatever the host order.
}

}  // namespace

std::string EncodeBinaryStl(const TriangleMesh& mesh, const std::string& solid_name) {
  constexpr size_t kHeaderBytes = 80;
  std::string out;
  out.reserve(kHeaderBytes + 4 + 50 * mesh.triangles.size());
  std::string header = "edgefit procedural mesh: " + solid_name;
  header.resize(kHeaderBytes, '\0');
  out += header;
  AppendUint32(static_cast<uint32_t>(mesh.triangles.size()), &out);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    Eigen::Vector3f corners[3];
    for (int k = 0; k < 3; ++k) corners[k] = mesh.vertices[t[k]].cast<float>();
    // The normal of the float corners a reader will see, computed in double.
    const Eigen::Vector3d a = corners[0].cast<double>();
    Eigen::Vector3d n = (corners[1].cast<double>() - a).cross(corners[2].cast<double>() - a);
    const double norm = n.norm();
    n = norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) AppendFloat(static_cast<float>(n[i]), &out);
    for (const Eigen::Vector3f& c : corners) {
      for (int i = 0; i < 3; ++i) AppendFloat(c[i], &out);
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
