// Shared checks of AddAccessories on a posed model (accessories_test.cc and
// accessories_robots_test.cc).
#ifndef EDGEFIT_TESTS_SCENE_ACCESSORY_CHECKS_H_
#define EDGEFIT_TESTS_SCENE_ACCESSORY_CHECKS_H_

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "edgefit/scene/accessories.h"
#include "edgefit/scene/model_scene.h"
#include "mesh_checks.h"

namespace edgefit {
namespace testing_scene {

struct PosedScene {
  std::vector<Pose> T_world_link;
  Scene scene;
  AccessoryReport report;
  double link_area = 0.0;  // [m^2] of all posed link meshes
};

inline PosedScene MakeAccessoryScene(const KinematicModel& model, const std::vector<double>& q,
                                     const AccessoryOptions& options) {
  PosedScene posed;
  posed.T_world_link = model.ForwardKinematics(q, PoseFromXyYaw(0.5, -0.2, 0.4));
  AddAccessories(model, q, posed.T_world_link, options, &posed.scene, &posed.report);
  for (const Link& link : model.links()) posed.link_area += link.mesh.SurfaceArea();
  return posed;
}

// Geometry checks every accessory must pass; `max_deep_fraction` of the
// checked vertices may lie more than 5 mm inside a link (where two link
// housings overlap at a joint the push-out cannot satisfy both).
inline void ExpectAccessoriesWellPlaced(const KinematicModel& model, const PosedScene& posed,
                                        double max_deep_fraction) {
  std::vector<TriangleMesh> links_world(model.links().size());
  std::vector<Eigen::AlignedBox3d> boxes(model.links().size());
  for (size_t k = 0; k < model.links().size(); ++k) {
    links_world[k].Append(model.links()[k].mesh, posed.T_world_link[k]);
    boxes[k] = links_world[k].BoundingBox();
  }
  int checked = 0, deep = 0;
  double deepest = 0.0;
  for (const AccessoryRecord& record : posed.report.records) {
    SCOPED_TRACE(record.kind + " #" + std::to_string(record.scene_index));
    ASSERT_GE(record.scene_index, 0);
    ASSERT_LT(record.scene_index, static_cast<int>(posed.scene.meshes.size()));
    const SceneMesh& mesh = posed.scene.meshes[record.scene_index];
    EXPECT_EQ(mesh.label, kLabelAccessory);
    EXPECT_EQ(mesh.link, -1);
    EXPECT_EQ(mesh.kind, record.kind);
    EXPECT_FALSE(mesh.mesh_world.empty());
    EXPECT_TRUE(AllFinite(mesh.mesh_world));
    EXPECT_TRUE(IsClosed(mesh.mesh_world));
    EXPECT_GT(record.area, 0.0);
    // Near the links: hoses loop out further than the rest.
    const double reach = record.kind == "hose" ? 0.3 : 0.2;
    const size_t stride = std::max<size_t>(1, mesh.mesh_world.vertices.size() / 300);
    for (size_t i = 0; i < mesh.mesh_world.vertices.size(); i += stride) {
      const Eigen::Vector3d& v = mesh.mesh_world.vertices[i];
      double distance = INFINITY;
      double depth = 0.0;
      for (size_t k = 0; k < boxes.size(); ++k) {
        if (boxes[k].isEmpty()) continue;
        distance = std::min(distance, boxes[k].exteriorDistance(v));
        depth = std::max(depth, PenetrationDepth(links_world[k], v));
      }
      EXPECT_LE(distance, reach) << v.transpose();
      ++checked;
      if (depth > 0.005) ++deep;
      deepest = std::max(deepest, depth);
    }
  }
  EXPECT_GT(checked, 0);
  EXPECT_LE(deep, max_deep_fraction * checked)
      << deep << " of " << checked << " vertices > 5 mm inside a link, deepest " << deepest;
  ::testing::Test::RecordProperty("deep_vertices", deep);
  ::testing::Test::RecordProperty("checked_vertices", checked);
}

inline void ExpectHarnessesLikeReal(const PosedScene& posed, const AccessoryOptions& options) {
  for (const AccessoryRecord& record : posed.report.records) {
    if (record.kind == "harness") {
      EXPECT_GE(record.radius, options.harness_radius_min);
      EXPECT_LE(record.radius, options.harness_radius_max);
      EXPECT_GE(record.radius, 0.010);
      EXPECT_LE(record.radius, 0.025);
      // Control points on at least two links: it crosses a joint.
      EXPECT_GE(std::set<int>(record.links.begin(), record.links.end()).size(), 2u);
      // The radius is really the mesh's: first ring vs start cap centre.
      const TriangleMesh& tube = posed.scene.meshes[record.scene_index].mesh_world;
      const Eigen::Vector3d& start = tube.vertices[tube.vertices.size() - 2];
      EXPECT_NEAR((tube.vertices[0] - start).norm(), record.radius, 1e-9);
    } else if (record.kind == "hose") {
      EXPECT_GE(record.radius, 0.006);
      EXPECT_LE(record.radius, 0.012);
    }
  }
}

inline void ExpectSameScene(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].kind, b.meshes[i].kind);
    EXPECT_EQ(a.meshes[i].mesh_world.vertices, b.meshes[i].mesh_world.vertices);
    EXPECT_EQ(a.meshes[i].mesh_world.triangles, b.meshes[i].mesh_world.triangles);
  }
}

}  // namespace testing_scene
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SCENE_ACCESSORY_CHECKS_H_
