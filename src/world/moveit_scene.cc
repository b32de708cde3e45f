#include "edgefit/world/moveit_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "edgefit/world/background_voxels.h"

namespace edgefit {
namespace {

using Voxel = std::array<int32_t, 3>;

int32_t TileOf(int32_t v, int tile) {
  return static_cast<int32_t>(std::floor(static_cast<double>(v) / tile));
}

}  // namespace

Status WriteMoveItScene(const std::vector<Voxel>& voxels, double voxel, int tile,
                        const std::string& name, const std::string& path) {
  if (tile < 1) return Status::Error("world: the scene's tile must be at least one voxel");
  std::map<Voxel, std::vector<Voxel>> tiles;  // ordered: the file is the same every run
  for (const Voxel& v : voxels) {
    tiles[{TileOf(v[0], tile), TileOf(v[1], tile), TileOf(v[2], tile)}].push_back(v);
  }
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) return Status::Error(path + ": cannot write it");
  std::fprintf(file, "%s\n", name.c_str());
  for (auto& [key, members] : tiles) {
    std::sort(members.begin(), members.end());
    const TriangleMesh mesh = VoxelUnionSurface(members, voxel);
    // The object and its one shape at the world origin: the mesh is in the
    // world frame. Colour 0 0 0 0: none.
    std::fprintf(file, "* background_%d_%d_%d\n0 0 0\n0 0 0 1\n1\nmesh\n%zu %zu\n", key[0], key[1],
                 key[2], mesh.vertices.size(), mesh.triangles.size());
    for (const Eigen::Vector3d& p : mesh.vertices) {
      std::fprintf(file, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    }
    for (const Eigen::Vector3i& t : mesh.triangles) std::fprintf(file, "%d %d %d\n", t[0], t[1], t[2]);
    std::fprintf(file, "0 0 0\n0 0 0 1\n0 0 0 0\n0\n");
  }
  std::fprintf(file, ".\n");
  const bool ok = std::ferror(file) == 0;
  if (std::fclose(file) != 0 || !ok) return Status::Error(path + ": cannot write it");
  return Status::Ok();
}

}  // namespace edgefit
