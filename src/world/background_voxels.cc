#include "edgefit/world/background_voxels.h"

#include <fcntl.h>
#include <octomap/OcTree.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "edgefit/core/split_mix64.h"
#include "edgefit/model/mesh_ply.h"
#include "edgefit/world/moveit_scene.h"
#include "fcl_mesh.h"

namespace edgefit {
namespace {

using Voxel = std::array<int32_t, 3>;

// Debian's liboctomap prints its debug lines (" done.") on stderr while it
// reads or writes a tree; edgefit's stderr holds progress and the one error
// line.
template <typename F>
bool Quietly(F&& io) {
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int null = ::open("/dev/null", O_WRONLY);
  if (saved >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
  const bool ok = io();
  std::fflush(stderr);
  if (saved >= 0) ::dup2(saved, STDERR_FILENO);
  if (saved >= 0) ::close(saved);
  if (null >= 0) ::close(null);
  return ok;
}

bool Contains(const std::vector<Voxel>& sorted, const Voxel& v) {
  return std::binary_search(sorted.begin(), sorted.end(), v);
}

}  // namespace

std::vector<Voxel> OccupiedVoxels(const std::vector<Eigen::Vector3f>& points, double voxel) {
  std::vector<Voxel> voxels;
  voxels.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    voxels.push_back(VoxelOf(p, voxel));
  }
  std::sort(voxels.begin(), voxels.end());
  voxels.erase(std::unique(voxels.begin(), voxels.end()), voxels.end());
  return voxels;
}

namespace {
// The rectangle a b d e on a plane `axis` = const, its corners in the order
// (u, w) = (0, 0), (1, 0), (1, 1), (0, 1) of the other axes u = axis + 1,
// w = axis + 2, as two triangles facing `side` (u x w = +axis: counter-
// clockwise from outside when side > 0).
void AddFace(int a, int b, int d, int e, int side, TriangleMesh* mesh) {
  if (side > 0) {
    mesh->triangles.emplace_back(a, b, d);
    mesh->triangles.emplace_back(a, d, e);
  } else {
    mesh->triangles.emplace_back(a, d, b);
    mesh->triangles.emplace_back(a, e, d);
  }
}

// Calls face(v, axis, side) for each outer face of the union: the side of
// voxel v facing `side` along `axis`, where no voxel is.
template <typename Face>
void ForEachOuterFace(const std::vector<Voxel>& voxels, const Face& face) {
  for (const Voxel& v : voxels) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const int side : {-1, 1}) {
        Voxel neighbour = v;
        neighbour[static_cast<size_t>(axis)] += side;
        if (!Contains(voxels, neighbour)) face(v, axis, side);
      }
    }
  }
}
}  // namespace

TriangleMesh VoxelUnionSurface(const std::vector<Voxel>& voxels, double voxel) {
  TriangleMesh mesh;
  struct CornerHash {
    size_t operator()(const Voxel& c) const {
      return static_cast<size_t>(Mix64((static_cast<uint64_t>(static_cast<uint32_t>(c[0])) << 42) ^
                                               (static_cast<uint64_t>(static_cast<uint32_t>(c[1])) << 21) ^
                                               static_cast<uint32_t>(c[2])));
    }
  };
  std::unordered_map<Voxel, int, CornerHash> corner_index;  // a corner (lattice point) -> vertex
  corner_index.reserve(2 * voxels.size());
  auto corner = [&](const Voxel& c) {
    const auto [it, added] = corner_index.emplace(c, static_cast<int>(mesh.vertices.size()));
    if (added) mesh.vertices.emplace_back(c[0] * voxel, c[1] * voxel, c[2] * voxel);
    return it->second;
  };
  ForEachOuterFace(voxels, [&](const Voxel& v, int axis, int side) {
    // The face's corners: on the plane `axis` = v + (side > 0), the two
    // other axes u, w spanning it.
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    Voxel c = v;
    c[static_cast<size_t>(axis)] += side > 0 ? 1 : 0;
    Voxel c00 = c, c10 = c, c11 = c, c01 = c;
    c10[static_cast<size_t>(u)] += 1;
    c11[static_cast<size_t>(u)] += 1;
    c11[static_cast<size_t>(w)] += 1;
    c01[static_cast<size_t>(w)] += 1;
    AddFace(corner(c00), corner(c10), corner(c11), corner(c01), side, &mesh);
  });
  return mesh;
}

TriangleMesh VoxelUnionRectangles(const std::vector<Voxel>& voxels, double voxel) {
  // Exposed faces as (axis, side, plane, w, u): the face on plane `axis` =
  // plane, facing `side`, covering cell (u, w) of the two other axes.
  using Face = std::array<int32_t, 5>;
  std::vector<Face> faces;
  ForEachOuterFace(voxels, [&](const Voxel& v, int axis, int side) {
    const size_t u = static_cast<size_t>((axis + 1) % 3), w = static_cast<size_t>((axis + 2) % 3);
    faces.push_back({axis, side, v[static_cast<size_t>(axis)] + (side > 0 ? 1 : 0), v[w], v[u]});
  });
  std::sort(faces.begin(), faces.end());
  // Rows: runs of consecutive u, as (axis, side, plane, u0, u1, w).
  using Row = std::array<int32_t, 6>;
  std::vector<Row> rows;
  for (size_t i = 0; i < faces.size();) {
    size_t end = i + 1;
    while (end < faces.size() && std::equal(faces[end].begin(), faces[end].begin() + 4, faces[i].begin()) &&
           faces[end][4] == faces[end - 1][4] + 1) {
      ++end;
    }
    rows.push_back({faces[i][0], faces[i][1], faces[i][2], faces[i][4], faces[end - 1][4] + 1, faces[i][3]});
    i = end;
  }
  // Rectangles: runs of consecutive w among rows of the same extent.
  std::sort(rows.begin(), rows.end());
  TriangleMesh mesh;
  for (size_t i = 0; i < rows.size();) {
    size_t end = i + 1;
    while (end < rows.size() && std::equal(rows[end].begin(), rows[end].begin() + 5, rows[i].begin()) &&
           rows[end][5] == rows[end - 1][5] + 1) {
      ++end;
    }
    const int axis = rows[i][0], side = rows[i][1];
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const auto corner = [&](int32_t cu, int32_t cw) {
      Eigen::Vector3d c;
      c[axis] = rows[i][2] * voxel;
      c[u] = cu * voxel;
      c[w] = cw * voxel;
      mesh.vertices.push_back(c);
      return static_cast<int>(mesh.vertices.size()) - 1;
    };
    const int32_t w0 = rows[i][5], w1 = rows[end - 1][5] + 1;
    AddFace(corner(rows[i][3], w0), corner(rows[i][4], w0), corner(rows[i][4], w1), corner(rows[i][3], w1), side,
            &mesh);
    i = end;
  }
  return mesh;
}

size_t CarveVoxels(const TriangleMesh& mesh_world, double voxel, double margin,
                   std::vector<Voxel>* voxels) {
  if (mesh_world.empty()) return 0;
  Eigen::AlignedBox3d box = mesh_world.BoundingBox(Pose::Identity());
  box.min().array() -= margin;
  box.max().array() += margin;
  Voxel low, high;
  for (int a = 0; a < 3; ++a) {
    low[static_cast<size_t>(a)] = static_cast<int32_t>(std::floor(box.min()[a] / voxel));
    high[static_cast<size_t>(a)] = static_cast<int32_t>(std::floor(box.max()[a] / voxel));
  }
  const FclMesh mesh(mesh_world);
  const size_t before = voxels->size();
  voxels->erase(std::remove_if(voxels->begin(), voxels->end(),
                               [&](const Voxel& v) {
                                 for (size_t a = 0; a < 3; ++a) {
                                   if (v[a] < low[a] || v[a] > high[a]) return false;
                                 }
                                 const Eigen::Vector3d corner(v[0] * voxel, v[1] * voxel, v[2] * voxel);
                                 return mesh.CollidesBox(
                                     Pose::Identity(),
                                     Eigen::AlignedBox3d(corner - Eigen::Vector3d::Constant(margin),
                                                         corner + Eigen::Vector3d::Constant(voxel + margin)));
                               }),
                voxels->end());
  return before - voxels->size();
}

Status ReadBackgroundVoxels(const std::string& path, const Eigen::AlignedBox3d& region,
                            std::vector<Voxel>* voxels, double* voxel) {
  voxels->clear();
  octomap::OcTree tree(0.1);
  if (!Quietly([&] { return tree.readBinary(path); })) {
    return Status::Error(path + ": cannot read it as an OctoMap binary tree (.bt)");
  }
  *voxel = tree.getResolution();
  const double v = *voxel;
  const auto point = [](const Eigen::Vector3d& p) {
    return octomap::point3d(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
  };
  // Within the tree's own bounds: octomap's keys do not reach far beyond.
  double x0, y0, z0, x1, y1, z1;
  tree.getMetricMin(x0, y0, z0);
  tree.getMetricMax(x1, y1, z1);
  const Eigen::AlignedBox3d within =
      region.intersection(Eigen::AlignedBox3d(Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1)));
  if (tree.size() == 0 || within.isEmpty()) return Status::Ok();
  for (auto it = tree.begin_leafs_bbx(point(within.min()), point(within.max())),
            end = tree.end_leafs_bbx();
       it != end; ++it) {
    if (!tree.isNodeOccupied(*it)) continue;
    // A pruned leaf spans 2^k cells along each axis.
    const double half = 0.5 * it.getSize();
    const int n = std::max(1, static_cast<int>(std::lround(it.getSize() / v)));
    const int32_t x0 = static_cast<int32_t>(std::lround((it.getX() - half) / v));
    const int32_t y0 = static_cast<int32_t>(std::lround((it.getY() - half) / v));
    const int32_t z0 = static_cast<int32_t>(std::lround((it.getZ() - half) / v));
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        for (int k = 0; k < n; ++k) voxels->push_back({x0 + i, y0 + j, z0 + k});
      }
    }
  }
  std::sort(voxels->begin(), voxels->end());
  voxels->erase(std::unique(voxels->begin(), voxels->end()), voxels->end());
  return Status::Ok();
}

Status WriteBackground(const std::vector<Voxel>& voxels, const BackgroundOptions& options,
                       const std::string& folder, std::vector<std::string>* names) {
  if (!(options.voxel > 0.0) || !std::isfinite(options.voxel)) {
    return Status::Error("world: the background voxel must be finite and > 0");
  }
  EDGEFIT_RETURN_IF_ERROR(WriteMeshPly(
      folder + "/background.ply", VoxelUnionSurface(voxels, options.voxel),
      "edgefit world: the background's occupied voxels of " + std::to_string(options.voxel) +
          " m, outer faces, world frame"));
  names->push_back("background.ply");
  EDGEFIT_RETURN_IF_ERROR(WriteMoveItScene(voxels, options.voxel, options.scene_tile, "edgefit_background",
                                           folder + "/background.scene"));
  names->push_back("background.scene");
  octomap::OcTree tree(options.voxel);
  for (const Voxel& v : voxels) {
    tree.updateNode(octomap::point3d(static_cast<float>((v[0] + 0.5) * options.voxel),
                                     static_cast<float>((v[1] + 0.5) * options.voxel),
                                     static_cast<float>((v[2] + 0.5) * options.voxel)),
                    true, /*lazy_eval=*/true);
  }
  tree.updateInnerOccupancy();
  tree.toMaxLikelihood();  // as octomap::OcTree::writeBinary does: binary cells, pruned
  tree.prune();
  const std::string bt = folder + "/background.bt";
  if (!Quietly([&] { return tree.writeBinaryConst(bt); })) return Status::Error(bt + ": cannot write the octree");
  names->push_back("background.bt");
  return Status::Ok();
}

}  // namespace edgefit
