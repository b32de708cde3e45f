#include "edgefit/model/surface_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

// Distance from p to the surface of the axis-aligned box of half sizes h.
double DistanceToBoxSurface(const Eigen::Vector3d& p, const Eigen::Vector3d& h) {
  const Eigen::Vector3d d = p.cwiseAbs() - h;
  if ((d.array() > 0).any()) return d.cwiseMax(0.0).norm();
  return -d.maxCoeff();
}

TEST(SurfaceSamplerTest, BoxCountPlacementNormalsAndDensity) {
  // Faces of very different size: 1 x 0.5 (x 2), 1 x 0.125, 0.5 x 0.125.
  const Eigen::Vector3d size(1.0, 0.5, 0.125), h = 0.5 * size;
  const TriangleMesh box = MakeBoxMesh(size);
  const double spacing = 0.01;
  const SurfaceSamples s = SampleMeshSurface(box, spacing, 7);
  const double area = box.SurfaceArea();
  EXPECT_EQ(s.size(), static_cast<size_t>(std::llround(area / (spacing * spacing))));
  ASSERT_EQ(s.normals.size(), s.size());
  std::vector<int> per_face(6, 0);  // Count per box face (two triangles each).
  for (size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector3d p = s.points[i].cast<double>();
    EXPECT_LT(DistanceToBoxSurface(p, h), 1e-9);
    // The normal is the outward axis of the face the point lies on.
    const Eigen::Vector3d n = s.normals[i].cast<double>();
    EXPECT_NEAR(n.norm(), 1.0, 1e-6);
    int axis;
    n.cwiseAbs().maxCoeff(&axis);
    EXPECT_NEAR(p[axis], n[axis] > 0 ? h[axis] : -h[axis], 1e-9);
    ++per_face[s.triangles[i] / 2];
  }
  // Density per face equals 1 / spacing^2 within a point (stratified
  // sampling: per-face counts are off by at most ~1 from area / spacing^2).
  for (int f = 0; f < 6; ++f) {
    const Eigen::Vector3i& t = box.triangles[2 * f];
    const double face_area = (box.vertices[t[1]] - box.vertices[t[0]])
                                 .cross(box.vertices[t[2]] - box.vertices[t[0]]).norm();
    EXPECT_NEAR(per_face[f], face_area / (spacing * spacing), 2.0) << "face " << f;
  }
}

TEST(SurfaceSamplerTest, UniformWithinATriangle) {
  // Quadrant counts on a right triangle split by its medians: each of the 4
  // sub-triangles has a quarter of the area.
  TriangleMesh tri;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  const SurfaceSamples s = SampleMeshSurface(tri, 0.002, 3);  // 125000 points.
  int counts[4] = {0, 0, 0, 0};
  for (const Eigen::Vector3f& p : s.points) {
    const int k = p.x() > 0.5 ? 1 : p.y() > 0.5 ? 2 : p.x() + p.y() < 0.5 ? 0 : 3;
    ++counts[k];
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(counts[k] / static_cast<double>(s.size()), 0.25, 0.01) << k;
  }
}

TEST(SurfaceSamplerTest, DeterministicPerSeedAndPerLink) {
  const TriangleMesh sphere = MakeSphereMesh(0.3, 3);
  const SurfaceSamples a = SampleMeshSurface(sphere, 0.01, 42);
  const SurfaceSamples b = SampleMeshSurface(sphere, 0.01, 42);
  const SurfaceSamples c = SampleMeshSurface(sphere, 0.01, 43);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.size(), c.size());
  EXPECT_NE(a.points, c.points);

  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf", {}, &model).ok());
  SamplingOptions options;
  options.spacing = 0.005;
  const std::vector<SurfaceSamples> first = SampleModelSurfaces(model, options);
  const std::vector<SurfaceSamples> second = SampleModelSurfaces(model, options);
  ASSERT_EQ(first.size(), model.links().size());
  for (size_t l = 0; l < first.size(); ++l) {
    EXPECT_EQ(first[l].points, second[l].points);
    EXPECT_EQ(first[l].points.empty(), model.links()[l].mesh.empty());
  }
  std::string error;
  options.spacing = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
}

TEST(SurfaceSamplerTest, TinyMeshGetsOnePointAndEmptyMeshNone) {
  const SurfaceSamples tiny = SampleMeshSurface(MakeBoxMesh(Eigen::Vector3d::Constant(1e-4)), 0.002, 1);
  EXPECT_EQ(tiny.size(), 1u);
  EXPECT_EQ(SampleMeshSurface(TriangleMesh(), 0.002, 1).size(), 0u);
}

}  // namespace
}  // namespace edgefit
