#include "edgefit/model/mesh_ply.h"

#include <cstdint>

#include "edgefit/core/atomic_file.h"
#include "edgefit/core/little_endian.h"

namespace edgefit {

std::string EncodeMeshPly(const TriangleMesh& mesh, const std::string& comment) {
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  if (!comment.empty()) out += "comment " + comment + "\n";
  out += "element vertex " + std::to_string(mesh.vertices.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " +
         std::to_string(mesh.triangles.size()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
  out.reserve(out.size() + 12 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (const Eigen::Vector3d& v : mesh.vertices) {
    for (int i = 0; i < 3; ++i) AppendFloatLE(static_cast<float>(v[i]), &out);
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    out.push_back(3);
    for (int i = 0; i < 3; ++i) AppendUint32LE(static_cast<uint32_t>(t[i]), &out);
  }
  return out;
}

Status WriteMeshPly(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
  return WriteStringAtomically(path, EncodeMeshPly(mesh, comment));
}

}  // namespace edgefit
