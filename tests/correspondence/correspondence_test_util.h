// Virtual scans of a box on a floor and of the posed fk_arm, CAD samples at
// the true pose, and the brute-force nearest scan point as ground truth.
#ifndef EDGEFIT_TESTS_CORRESPONDENCE_CORRESPONDENCE_TEST_UTIL_H_
#define EDGEFIT_TESTS_CORRESPONDENCE_CORRESPONDENCE_TEST_UTIL_H_

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/correspondence/correspondences.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/model_scene.h"
#include "edgefit/scene/scene.h"

namespace edgefit {
namespace testing_util {

struct CorrespondenceFixture {
  ScanSet scans;
  std::vector<Eigen::Vector3f> q_world;  // CAD samples at the true pose
  Eigen::AlignedBox3d asset_box_world;
};

inline SceneMesh Floor() {
  SceneMesh m;
  m.mesh_world.vertices = {{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}};
  m.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.label = kLabelBackground;
  m.kind = "floor";
  return m;
}

// Every `stride`-th sample, posed into the world.
inline void AppendSamples(const SurfaceSamples& samples, const Pose& T_world_mesh, size_t stride,
                          std::vector<Eigen::Vector3f>* q_world) {
  for (size_t i = 0; i < samples.size(); i += stride) {
    q_world->push_back((T_world_mesh * samples.points[i].cast<double>()).cast<float>());
  }
}

inline void ScanAsset(const Scene& scene, const Eigen::AlignedBox3d& box,
                      CorrespondenceFixture* f) {
  ScannerPlacementOptions placement;
  placement.count = 3;
  placement.min_distance = 1.5;
  placement.max_distance = 2.5;
  placement.seed = 7;
  VirtualScanOptions options;  // 1.7 mm spacing, 1 mm noise
  VirtualScan scan;
  CHECK(ScanScene(scene, PlaceScanners(box, placement), options, &scan).ok());
  f->scans = std::move(scan.scans);
  f->asset_box_world = box;
}

// A 0.30 x 0.20 x 0.25 m box standing on the floor, yawed.
inline CorrespondenceFixture MakeBoxFixture(size_t stride) {
  CorrespondenceFixture f;
  const Eigen::Vector3d size(0.30, 0.20, 0.25);
  const Pose T_world_box = PoseFromXyzRpy({0.1, -0.05, 0.125}, {0, 0, 0.4});
  const TriangleMesh box_mesh = MakeBoxMesh(size);
  Scene scene;
  scene.meshes.push_back(Floor());
  SceneMesh box;
  box.mesh_world = box_mesh;
  for (Eigen::Vector3d& v : box.mesh_world.vertices) v = T_world_box * v;
  box.label = LinkLabel(0);
  box.link = 0;
  box.kind = "link";
  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3d& v : box.mesh_world.vertices) bounds.extend(v);
  scene.meshes.push_back(box);
  ScanAsset(scene, bounds, &f);
  AppendSamples(SampleMeshSurface(box_mesh, 0.002, 3), T_world_box, stride, &f.q_world);
  return f;
}

// assets/models/fk_arm.urdf at a random posture on the floor.
inline CorrespondenceFixture MakeFkArmFixture(size_t stride) {
  CorrespondenceFixture f;
  KinematicModel model;
  CHECK(LoadKinematicModel(EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf", {}, &model).ok());
  const std::vector<double> q = RandomJointValues(model, 3);
  const Pose T_world_base = PoseFromXyYaw(0.3, -0.2, 0.4);
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  Scene scene;
  scene.meshes.push_back(Floor());
  AddModelToScene(model, T_world_link, &scene);
  ScanAsset(scene, model.BoundingBox(q, T_world_base), &f);
  SamplingOptions sampling;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
  for (size_t l = 0; l < samples.size(); ++l) {
    AppendSamples(samples[l], T_world_link[l], stride, &f.q_world);
  }
  return f;
}

// Exact nearest valid scan point of every query (world frame, float, like
// the kd-tree), no gate: scan -1 only when there are no points.
inline std::vector<Correspondence> BruteForceNearest(const ScanSet& scans,
                                                     const std::vector<Eigen::Vector3f>& q_world) {
  std::vector<Eigen::Vector3f> p_world;
  std::vector<int> scan_of, cell_of;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    for (size_t i = 0; i < scans.scans[s].size(); ++i) {
      if (!scans.scans[s].IsValid(i)) continue;
      p_world.push_back(scans.scans[s].PointWorld(i).cast<float>());
      scan_of.push_back(static_cast<int>(s));
      cell_of.push_back(static_cast<int>(i));
    }
  }
  std::vector<Correspondence> out(q_world.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (int64_t k = 0; k < static_cast<int64_t>(q_world.size()); ++k) {
    float best = std::numeric_limits<float>::infinity();
    size_t best_j = 0;
    for (size_t j = 0; j < p_world.size(); ++j) {
      const float d2 = (p_world[j] - q_world[k]).squaredNorm();
      if (d2 < best) {
        best = d2;
        best_j = j;
      }
    }
    Correspondence& c = out[static_cast<size_t>(k)];
    c.source = static_cast<int>(k);
    if (!p_world.empty()) {
      c.scan = scan_of[best_j];
      c.cell = cell_of[best_j];
      c.distance = (p_world[best_j] - q_world[k]).norm();
    }
  }
  return out;
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_CORRESPONDENCE_CORRESPONDENCE_TEST_UTIL_H_
