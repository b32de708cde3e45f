#include "edgefit/model/mesh_loader.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <exception>
#include <utility>

namespace edgefit {
namespace {

Eigen::Matrix4d ToEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
      m.d3, m.d4;
  return out;
}

// Appends the meshes of `node` and its children, each posed by the product of
// the node transforms from the root (root included: it holds the unit scale).
void AppendNode(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& T_parent,
                TriangleMesh* out) {
  const Eigen::Matrix4d T_node = T_parent * ToEigen(node.mTransformation);
  for (unsigned int m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int offset = static_cast<int>(out->vertices.size());
    for (unsigned int v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      out->vertices.push_back((T_node * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
    }
    for (unsigned int f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // Points and lines: no surface.
      out->triangles.emplace_back(offset + static_cast<int>(face.mIndices[0]),
                                  offset + static_cast<int>(face.mIndices[1]),
                                  offset + static_cast<int>(face.mIndices[2]));
    }
  }
  for (unsigned int c = 0; c < node.mNumChildren; ++c) {
    AppendNode(scene, *node.mChildren[c], T_node, out);
  }
}

}  // namespace

void ScaleMesh(const Eigen::Vector3d& scale, TriangleMesh* mesh) {
  for (Eigen::Vector3d& v : mesh->vertices) v = v.cwiseProduct(scale);
  if (scale.prod() < 0.0) {
    for (Eigen::Vector3i& t : mesh->triangles) std::swap(t[1], t[2]);
  }
}

Status LoadMesh(const std::string& path, const Eigen::Vector3d& scale, TriangleMesh* mesh) {
  TriangleMesh loaded;
  try {
    Assimp::Importer importer;
    // Keep COLLADA Z_UP files Z up, as ROS tools display them; the unit scale
    // stays in the root node transform, which AppendNode applies.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_SortByPType);
    if (scene == nullptr || scene->mRootNode == nullptr) {
      return Status::Error(path + ": cannot read mesh: " + importer.GetErrorString());
    }
    AppendNode(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), &loaded);
  } catch (const std::exception& e) {  // assimp reports by return value; be safe.
    return Status::Error(path + ": cannot read mesh: " + e.what());
  }
  WeldIdenticalVertices(&loaded);
  if (loaded.empty()) return Status::Error(path + ": mesh has no triangles");
  ScaleMesh(scale, &loaded);
  *mesh = std::move(loaded);
  return Status::Ok();
}

}  // namespace edgefit
