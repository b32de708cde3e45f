// The least distance over pairs of posed meshes (src/world/least_distance.h):
// exact whatever the first cap, the first contact in sphere order, a
// cached pair's answer kept only while its relative pose is, and its bound
// at a new pose below the distance there.
#include "src/world/least_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "edgefit/model/primitive_meshes.h"

namespace edgefit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Pose At(double x) {
  Pose T = Pose::Identity();
  T.translation().x() = x;
  return T;
}

TEST(LeastDistanceTest, ExactFromAnyCapAndTheFirstContact) {
  const FclMesh cube(MakeBoxMesh(Eigen::Vector3d::Ones()));  // 1 m, centred
  const Pose origin = At(0.0), near = At(1.25), far = At(4.0), crossing = At(0.99);
  // Distances between faces: 0.25 m and 3 m.
  const std::vector<MeshPair> pairs = {{2.0, 0, 2, &cube, &origin, &cube, &far, -1},
                                       {0.0, 0, 1, &cube, &origin, &cube, &near, -1}};
  for (const double cap : {1e-9, 0.01, 0.25, 0.3, 10.0, kInf}) {
    const LeastDistance least = FindLeastDistance(pairs, kInf, cap, nullptr);
    EXPECT_NEAR(least.distance, 0.25, 1e-12) << cap;
    EXPECT_FALSE(least.contact);
  }
  // Below a start nearer than every pair: the start.
  EXPECT_EQ(FindLeastDistance(pairs, 0.2, kInf, nullptr).distance, 0.2);
  // Contact: the crossing pair, not the farther one.
  const std::vector<MeshPair> contact = {{0.0, 0, 1, &cube, &origin, &cube, &near, -1},
                                         {0.0, 0, 3, &cube, &origin, &cube, &crossing, -1}};
  const LeastDistance hit = FindLeastDistance(contact, kInf, kInf, nullptr);
  EXPECT_EQ(hit.distance, 0.0);
  ASSERT_TRUE(hit.contact);
  EXPECT_EQ(hit.contact_b, 3);
  EXPECT_NEAR(hit.p_world.x(), 0.495, 0.0051);  // where they cross
  const LeastDistance first = FindContact(contact);
  ASSERT_TRUE(first.contact);
  EXPECT_EQ(first.contact_b, 3);
  EXPECT_TRUE(std::isinf(FindContact(pairs).distance));
}

TEST(LeastDistanceTest, ACachedPairKeepsItsDistanceWhileItsPoseDoes) {
  const FclMesh cube(MakeBoxMesh(Eigen::Vector3d::Ones()));
  Pose a = At(0.0), b = At(1.5);
  PairCache cache(1);
  const MeshPair pair{0.0, 0, 1, &cube, &a, &cube, &b, 0};
  EXPECT_NEAR(cache.Distance(pair, kInf), 0.5, 1e-12);
  // Both moved together: the same relative pose, the same answer.
  a.translation().y() = 3.0;
  b.translation().y() = 3.0;
  EXPECT_NEAR(cache.Distance(pair, kInf), 0.5, 1e-12);
  EXPECT_EQ(cache.Distance(pair, 0.4), 0.4);  // sought below 0.4: not there
  // b moved: measured again.
  b.translation().x() = 1.2;
  EXPECT_NEAR(cache.Distance(pair, kInf), 0.2, 1e-12);
  // Known only to be beyond a limit: sought again below a higher one.
  b.translation().x() = 3.0;
  EXPECT_EQ(cache.Distance(pair, 1.0), 1.0);
  EXPECT_NEAR(cache.Distance(pair, kInf), 2.0, 1e-12);
}

TEST(LeastDistanceTest, ACachedPairBoundsItsDistanceWhereverItMoves) {
  const FclMesh cube(MakeBoxMesh(Eigen::Vector3d::Ones()));
  Pose a = At(0.0), b = At(3.0);
  PairCache cache(1);
  // Mesh a's sphere: centre 0, radius sqrt(3)/2 (the cube's corners).
  const MeshPair pair{0.0, 0, 1, &cube, &a, &cube, &b, 0, Eigen::Vector3d::Zero(), std::sqrt(3.0) / 2};
  EXPECT_EQ(cache.LowerBound(pair), 0.0);  // nothing found yet
  EXPECT_NEAR(cache.Distance(pair, kInf), 2.0, 1e-12);
  // a slid 0.5 m toward b: at most 0.5 nearer.
  a.translation().x() = 0.5;
  EXPECT_NEAR(cache.LowerBound(pair), 1.5, 1e-12);
  // a turned 0.1 rad about its centre: its corners moved up to 0.1 * sqrt(3)/2.
  a.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const double bound = cache.LowerBound(pair);
  EXPECT_NEAR(bound, 1.5 - 0.1 * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_LE(bound, cube.Distance(a, cube, b, kInf));
  // Known only beyond a limit: the limit is the bound.
  a = At(0.2);  // 1.8 m apart
  EXPECT_EQ(cache.Distance(pair, 1.0), 1.0);
  EXPECT_NEAR(cache.LowerBound(pair), 1.0, 1e-12);
  // Over a run of poses, the search with the cache finds what it finds without.
  for (int k = 0; k < 40; ++k) {
    a.translation() = Eigen::Vector3d(0.05 * k, 0.3 * std::sin(0.3 * k), 0.0);
    a.linear() = Eigen::AngleAxisd(0.07 * k, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const double with = FindLeastDistance({pair}, kInf, kInf, &cache).distance;
    EXPECT_NEAR(with, FindLeastDistance({pair}, kInf, kInf, nullptr).distance, 1e-12) << k;
  }
}

}  // namespace
}  // namespace edgefit
