#include "edgefit/scene/environment.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/core/angles.h"
#include "edgefit/core/pose.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/core/split_mix64.h"

namespace edgefit {
namespace {

// Appends a box of full edge lengths `size` whose centre is `center` in the
// object frame.
void AddBox(const Eigen::Vector3d& size, const Eigen::Vector3d& center, TriangleMesh* mesh) {
  mesh->Append(MakeBoxMesh(size), Eigen::Isometry3d(Eigen::Translation3d(center)));
}

// A square or round pillar, 3.5-6 m tall, 0.3-0.6 m wide.
TriangleMesh MakePillar(SplitMix64* rng) {
  TriangleMesh mesh;
  const double height = rng->Uniform(3.5, 6.0);
  const double width = rng->Uniform(0.3, 0.6);
  if (rng->Uniform() < 0.5) {
    AddBox(Eigen::Vector3d(width, width, height), Eigen::Vector3d(0, 0, height / 2), &mesh);
  } else {
    mesh.Append(MakeCylinderMesh(width / 2, height, 32),
                Eigen::Isometry3d(Eigen::Translation3d(0, 0, height / 2)));
  }
  return mesh;
}

// A EUR-style pallet (1.2 x 0.8 m: three runners, a deck) with 1-3 boxes.
TriangleMesh MakePallet(SplitMix64* rng) {
  TriangleMesh mesh;
  const double length = 1.2, width = 0.8, runner_h = 0.1, deck_h = 0.044;
  for (int i = 0; i < 3; ++i) {
    const double y = (i - 1) * (width - 0.1) / 2;
    AddBox(Eigen::Vector3d(length, 0.1, runner_h), Eigen::Vector3d(0, y, runner_h / 2), &mesh);
  }
  AddBox(Eigen::Vector3d(length, width, deck_h), Eigen::Vector3d(0, 0, runner_h + deck_h / 2),
         &mesh);
  const int boxes = rng->Int(1, 3);
  const double slot = length / boxes;
  for (int i = 0; i < boxes; ++i) {
    const Eigen::Vector3d size(slot * rng->Uniform(0.7, 0.95), width * rng->Uniform(0.6, 0.95),
                               rng->Uniform(0.3, 1.0));
    const double x = -length / 2 + slot * (i + 0.5);
    AddBox(size, Eigen::Vector3d(x, 0, runner_h + deck_h + size.z() / 2), &mesh);
  }
  return mesh;
}

// A safety-fence panel along x: two posts, top/bottom rails, and vertical
// wire bars every 5 cm (a mesh seen edge-on by a scanner).
TriangleMesh MakeFence(SplitMix64* rng) {
  TriangleMesh mesh;
  const double width = rng->Uniform(1.5, 2.5), height = rng->Uniform(1.8, 2.2);
  const double post = 0.05, rail = 0.03, bar = 0.006, bar_pitch = 0.05;
  for (int side : {-1, 1}) {
    AddBox(Eigen::Vector3d(post, post, height), Eigen::Vector3d(side * (width - post) / 2, 0,
                                                                height / 2), &mesh);
  }
  const double inner = width - 2 * post;
  for (double z : {0.15, height - rail / 2}) {
    AddBox(Eigen::Vector3d(inner, rail, rail), Eigen::Vector3d(0, 0, z), &mesh);
  }
  const int bars = static_cast<int>(std::floor(inner / bar_pitch));
  const double bar_z0 = 0.15 + rail / 2, bar_z1 = height - rail;
  for (int i = 1; i < bars; ++i) {
    AddBox(Eigen::Vector3d(bar, bar, bar_z1 - bar_z0),
           Eigen::Vector3d(-inner / 2 + i * bar_pitch, 0, (bar_z0 + bar_z1) / 2), &mesh);
  }
  return mesh;
}

// True when the x-y extents of a and b overlap.
bool OverlapsXy(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return a.min().x() < b.max().x() && b.min().x() < a.max().x() && a.min().y() < b.max().y() &&
         b.min().y() < a.max().y();
}

}  // namespace

bool EnvironmentOptions::IsValid(std::string* error) const {
  if (!std::isfinite(floor_z)) {
    *error = "floor_z must be finite";
  } else if (!(floor_half_extent > 0.0) || !(floor_thickness > 0.0)) {
    *error = "floor_half_extent and floor_thickness must be positive [m]";
  } else if (clutter_count < 0) {
    *error = "clutter_count must be >= 0";
  } else if (!(keep_out_margin >= 0.0) || !(clutter_max_distance > keep_out_margin)) {
    *error = "need 0 <= keep_out_margin < clutter_max_distance [m]";
  } else {
    return true;
  }
  return false;
}

void AddEnvironment(const Eigen::AlignedBox3d& asset_box_world, const EnvironmentOptions& options,
                    Scene* scene) {
  CHECK(scene != nullptr);
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  Eigen::AlignedBox3d asset = asset_box_world;
  if (asset.isEmpty()) asset = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());

  Eigen::AlignedBox3d keep_out = asset, ring = asset;
  const Eigen::Vector3d margin(options.keep_out_margin, options.keep_out_margin, 0.0);
  const Eigen::Vector3d reach(options.clutter_max_distance, options.clutter_max_distance, 0.0);
  keep_out.min() -= margin;
  keep_out.max() += margin;
  ring.min() -= reach;
  ring.max() += reach;

  // Clutter first, so the floor can be grown to carry it.
  SplitMix64 rng = SplitMix64::Stream(options.seed, 0x656e76);  // "env"
  static const char* const kKinds[] = {"pillar", "pallet", "fence"};
  const int kind_offset = rng.Int(0, 2);
  std::vector<Eigen::AlignedBox3d> placed;
  std::vector<SceneMesh> clutter;
  for (int i = 0; i < options.clutter_count; ++i) {
    const int kind = (kind_offset + i) % 3;
    TriangleMesh object =
        kind == 0 ? MakePillar(&rng) : kind == 1 ? MakePallet(&rng) : MakeFence(&rng);
    bool done = false;
    for (int attempt = 0; attempt < 200 && !done; ++attempt) {
      const double x = rng.Uniform(ring.min().x(), ring.max().x());
      const double y = rng.Uniform(ring.min().y(), ring.max().y());
      const double yaw = rng.Uniform(-kPi, kPi);
      const Pose T_world_object =
          Eigen::Translation3d(0, 0, options.floor_z) * PoseFromXyYaw(x, y, yaw);
      const Eigen::AlignedBox3d box = object.BoundingBox(T_world_object);
      if (OverlapsXy(box, keep_out)) continue;
      if (box.min().x() < ring.min().x() || box.max().x() > ring.max().x() ||
          box.min().y() < ring.min().y() || box.max().y() > ring.max().y()) {
        continue;
      }
      // 0.3 m between objects keeps them apart for the scanner.
      Eigen::AlignedBox3d grown = box;
      grown.min() -= Eigen::Vector3d::Constant(0.3);
      grown.max() += Eigen::Vector3d::Constant(0.3);
      if (std::any_of(placed.begin(), placed.end(),
                      [&](const Eigen::AlignedBox3d& other) { return OverlapsXy(grown, other); })) {
        continue;
      }
      SceneMesh mesh;
      mesh.mesh_world.Append(object, T_world_object);
      mesh.label = kLabelBackground;
      mesh.kind = kKinds[kind];
      clutter.push_back(std::move(mesh));
      placed.push_back(box);
      done = true;
    }
    if (!done) LOG(WARNING) << "AddEnvironment: no free spot for clutter object " << i << " ("
                            << kKinds[kind] << "); left out";
  }

  if (options.add_floor) {
    const Eigen::Vector3d center = asset.center();
    double half = options.floor_half_extent;
    for (const Eigen::AlignedBox3d& box : placed) {
      half = std::max({half, std::abs(box.min().x() - center.x()) + 1.0,
                       std::abs(box.max().x() - center.x()) + 1.0,
                       std::abs(box.min().y() - center.y()) + 1.0,
                       std::abs(box.max().y() - center.y()) + 1.0});
    }
    SceneMesh floor;
    floor.mesh_world = MakeBoxMesh(Eigen::Vector3d(2 * half, 2 * half, options.floor_thickness));
    for (Eigen::Vector3d& v : floor.mesh_world.vertices) {
      v += Eigen::Vector3d(center.x(), center.y(), options.floor_z - options.floor_thickness / 2);
    }
    floor.label = kLabelBackground;
    floor.kind = "floor";
    floor.reflectance = 0.3;  // concrete
    scene->meshes.push_back(std::move(floor));
  }
  for (SceneMesh& mesh : clutter) scene->meshes.push_back(std::move(mesh));
}

}  // namespace edgefit
