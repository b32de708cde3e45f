// Lattice search (paper Sec. 5.2.1) against the brute-force nearest point on
// virtual scans (1.7 mm spacing, 1 mm noise) of a box and of the fk_arm.
#include "edgefit/correspondence/lattice_search.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <map>
#include <string>

#include "correspondence/correspondence_test_util.h"
#include "edgefit/correspondence/correspondence_search.h"

namespace edgefit {
namespace {

using testing_util::CorrespondenceFixture;

// Built once per scene: scanning and brute force take seconds.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

struct Cached {
  CorrespondenceFixture fixture;
  std::vector<Correspondence> brute_force;
};

const Cached& GetScene(const std::string& name) {
  static std::map<std::string, Cached>* cache = new std::map<std::string, Cached>;
  auto it = cache->find(name);
  if (it == cache->end()) {
    Cached c;
    // Under the sanitizers a quarter of the fk_arm's queries: the
    // brute-force reference is quadratic, and instrumenting it tests nothing.
    c.fixture = name == "Box" ? testing_util::MakeBoxFixture(40)
                              : testing_util::MakeFkArmFixture(kSanitized ? 200 : 50);
    c.brute_force = testing_util::BruteForceNearest(c.fixture.scans, c.fixture.q_world);
    it = cache->emplace(name, std::move(c)).first;
  }
  return it->second;
}

class LatticeSearchTest : public ::testing::TestWithParam<std::string> {};

// For CAD samples on a scanned surface (true nearest point within 3 mm, 3
// sigma of the noise) window 2 finds that very point (measured: 100% on both
// scenes). Samples on faces no scanner saw (the box's back and bottom) project
// onto the occluding front face, so over all queries passing the 5 cm gate
// the agreement is lower (measured 0.775 box, 0.863 fk_arm): the documented
// limit of the lattice. It never reports a point closer than the true nearest
// (subset search).
TEST_P(LatticeSearchTest, MatchesBruteForceNearest) {
  const Cached& c = GetScene(GetParam());
  const CorrespondenceFixture& f = c.fixture;
  ASSERT_GT(f.q_world.size(), 1000u);
  LatticeSearch search(&f.scans, nullptr);
  CorrespondenceOptions options;
  options.window = 2;
  std::vector<Correspondence> lattice;
  search.Find(f.q_world, options, &lattice);
  std::vector<const Correspondence*> by_source(f.q_world.size(), nullptr);
  for (const Correspondence& m : lattice) by_source[static_cast<size_t>(m.source)] = &m;

  size_t gated = 0, same = 0, seen = 0, seen_same = 0;
  for (size_t i = 0; i < f.q_world.size(); ++i) {
    const Correspondence& truth = c.brute_force[i];
    const Correspondence* m = by_source[i];
    if (m != nullptr) {
      EXPECT_GE(m->distance, truth.distance - 1e-5f) << "query " << i;
      EXPECT_LE(m->distance, options.max_distance);
    }
    if (truth.distance > options.max_distance) continue;
    ++gated;
    const bool equal = m != nullptr && m->scan == truth.scan && m->cell == truth.cell;
    same += equal;
    // On a scanned surface: within 3 sigma of the noise.
    if (truth.distance <= 0.003f) {
      ++seen;
      seen_same += equal;
    }
  }
  const double agreement = static_cast<double>(same) / static_cast<double>(gated);
  const double seen_agreement = static_cast<double>(seen_same) / static_cast<double>(seen);
  std::printf("[ %s ] %zu queries, %zu gated: lattice == brute force for %.4f; "
              "%zu within 3 mm: %.4f\n",
              GetParam().c_str(), f.q_world.size(), gated, agreement, seen, seen_agreement);
  EXPECT_GE(seen_agreement, 0.99);
  EXPECT_GE(agreement, 0.70);
}

TEST_P(LatticeSearchTest, SameOutputForOneAndTwoThreads) {
  const CorrespondenceFixture& f = GetScene(GetParam()).fixture;
  LatticeSearch search(&f.scans, nullptr);
  CorrespondenceOptions options;
  std::vector<Correspondence> one, two;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  search.Find(f.q_world, options, &one);
  omp_set_num_threads(2);
  search.Find(f.q_world, options, &two);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].source, two[i].source);
    EXPECT_EQ(one[i].scan, two[i].scan);
    EXPECT_EQ(one[i].cell, two[i].cell);
    EXPECT_EQ(one[i].distance, two[i].distance);
    if (i > 0) {
      EXPECT_LT(one[i - 1].source, one[i].source);
    }
  }
}

TEST_P(LatticeSearchTest, GateKeepsExactlyTheCloseMatches) {
  const CorrespondenceFixture& f = GetScene(GetParam()).fixture;
  LatticeSearch search(&f.scans, nullptr);
  CorrespondenceOptions wide, narrow;
  wide.max_distance = 1.0;
  narrow.max_distance = 0.0008;
  std::vector<Correspondence> all, close;
  search.Find(f.q_world, wide, &all);
  search.Find(f.q_world, narrow, &close);
  std::vector<Correspondence> expected;
  for (const Correspondence& m : all) {
    if (m.distance <= narrow.max_distance) expected.push_back(m);
  }
  ASSERT_EQ(close.size(), expected.size());
  EXPECT_LT(close.size(), all.size());
  for (size_t i = 0; i < close.size(); ++i) {
    EXPECT_EQ(close[i].source, expected[i].source);
    EXPECT_EQ(close[i].cell, expected[i].cell);
  }
}

TEST_P(LatticeSearchTest, WeightsComeFromTheTargetCell) {
  const CorrespondenceFixture& f = GetScene(GetParam()).fixture;
  CellWeights weights(f.scans.scans.size());
  for (size_t s = 0; s < weights.size(); ++s) {
    weights[s].resize(f.scans.scans[s].size());
    for (size_t i = 0; i < weights[s].size(); ++i) weights[s][i] = 0.5f + s + (i % 101) / 101.f;
  }
  CorrespondenceSearch search(&f.scans, &weights);
  for (const bool use_lattice : {true, false}) {
    CorrespondenceOptions options;
    options.use_lattice = use_lattice;
    std::vector<Correspondence> matches;
    search.Find(f.q_world, f.asset_box_world, options, &matches);
    ASSERT_FALSE(matches.empty());
    for (const Correspondence& m : matches) {
      EXPECT_EQ(m.weight, weights[static_cast<size_t>(m.scan)][static_cast<size_t>(m.cell)]);
    }
  }
  LatticeSearch unweighted(&f.scans, nullptr);
  std::vector<Correspondence> matches;
  unweighted.Find(f.q_world, CorrespondenceOptions(), &matches);
  for (const Correspondence& m : matches) EXPECT_EQ(m.weight, 1.f);
}

// Far above the asset (beyond every scan's top row), and at a scanner's
// origin: no scan's lattice covers them, so no match even with a 100 m gate.
TEST_P(LatticeSearchTest, PointsOutsideEveryGridGetNoMatch) {
  const CorrespondenceFixture& f = GetScene(GetParam()).fixture;
  LatticeSearch search(&f.scans, nullptr);
  CorrespondenceOptions options;
  options.max_distance = 100.0;
  std::vector<Eigen::Vector3f> q_world;
  const Eigen::Vector3d centre = f.asset_box_world.center();
  for (int k = 0; k < 10; ++k) {
    q_world.push_back((centre + Eigen::Vector3d(0.01 * k, 0.0, 30.0)).cast<float>());
  }
  q_world.push_back(f.scans.scans[0].T_world_scanner().translation().cast<float>());
  std::vector<Correspondence> matches;
  search.Find(q_world, options, &matches);
  EXPECT_TRUE(matches.empty());
  // The same points do have a (far) nearest point for the kd-tree.
  KdTreeSearch kdtree(&f.scans, nullptr);
  Eigen::AlignedBox3d everything(Eigen::Vector3d::Constant(-1e3), Eigen::Vector3d::Constant(1e3));
  kdtree.Find(q_world, everything, options, &matches);
  EXPECT_EQ(matches.size(), q_world.size());
}

TEST_P(LatticeSearchTest, KdTreeEqualsBruteForce) {
  const Cached& c = GetScene(GetParam());
  const CorrespondenceFixture& f = c.fixture;
  KdTreeSearch search(&f.scans, nullptr);
  CorrespondenceOptions options;
  options.max_distance = 10.0;  // every query matches
  const Eigen::AlignedBox3d everything(Eigen::Vector3d::Constant(-1e3),
                                       Eigen::Vector3d::Constant(1e3));
  std::vector<Correspondence> matches;
  search.Find(f.q_world, everything, options, &matches);
  ASSERT_EQ(matches.size(), f.q_world.size());
  EXPECT_EQ(search.size(), f.scans.TotalValid());
  for (size_t i = 0; i < matches.size(); ++i) {
    const Correspondence& truth = c.brute_force[i];
    EXPECT_EQ(matches[i].source, static_cast<int>(i));
    EXPECT_EQ(matches[i].scan, truth.scan) << "query " << i;
    EXPECT_EQ(matches[i].cell, truth.cell) << "query " << i;
    EXPECT_EQ(matches[i].distance, truth.distance);
  }
  // Same crop: no rebuild. A new crop holds only points inside it.
  EXPECT_FALSE(search.SetCrop(everything));
  Eigen::AlignedBox3d crop = f.asset_box_world;
  crop.extend(crop.min() - Eigen::Vector3d::Constant(0.05));
  crop.extend(crop.max() + Eigen::Vector3d::Constant(0.05));
  options.max_distance = 0.05;
  search.Find(f.q_world, crop, options, &matches);
  EXPECT_LT(search.size(), f.scans.TotalValid());
  for (const Correspondence& m : matches) {
    const Eigen::Vector3d p_world =
        f.scans.scans[static_cast<size_t>(m.scan)].PointWorld(static_cast<size_t>(m.cell));
    EXPECT_TRUE(crop.contains(p_world));
    EXPECT_LE(m.distance, 0.05f);
  }
}

// Cells marked `missing` (the refinement's mixed pixels) are searched as if
// the beam had returned nothing: the same matches as on a copy of the scans
// with those cells missing, for both searchers; `excluded` cells instead
// keep their matches, at weight 0.
TEST_P(LatticeSearchTest, MissingCellsMatchAsACopyWithoutThem) {
  const CorrespondenceFixture& f = GetScene(GetParam()).fixture;
  CellMask mask(f.scans.scans.size());
  ScanSet without = f.scans;
  size_t marked = 0;
  for (size_t s = 0; s < mask.size(); ++s) {
    mask[s].assign(f.scans.scans[s].size(), 0);
    for (size_t i = 0; i < mask[s].size(); ++i) {
      if (!f.scans.scans[s].IsValid(i) || (i * 7 + s) % 5 != 0) continue;
      mask[s][i] = 1;
      without.scans[s].SetMissing(i);
      ++marked;
    }
  }
  ASSERT_GT(marked, 1000u);
  const Eigen::AlignedBox3d everything(Eigen::Vector3d::Constant(-1e3),
                                       Eigen::Vector3d::Constant(1e3));
  for (const bool use_lattice : {true, false}) {
    CorrespondenceOptions options;
    options.use_lattice = use_lattice;
    CorrespondenceSearch masked(&f.scans, nullptr, nullptr, &mask);
    CorrespondenceSearch copy(&without, nullptr);
    std::vector<Correspondence> a, b;
    masked.Find(f.q_world, everything, options, &a);
    copy.Find(f.q_world, everything, options, &b);
    ASSERT_GT(a.size(), 100u);
    ASSERT_EQ(a.size(), b.size()) << "lattice " << use_lattice;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].source, b[i].source);
      EXPECT_EQ(a[i].scan, b[i].scan);
      EXPECT_EQ(a[i].cell, b[i].cell);
      EXPECT_EQ(a[i].distance, b[i].distance);
      EXPECT_EQ(mask[static_cast<size_t>(a[i].scan)][static_cast<size_t>(a[i].cell)], 0);
    }
    // The same cells excluded: some samples match them, at weight 0.
    CorrespondenceSearch excluded(&f.scans, nullptr, &mask);
    excluded.Find(f.q_world, everything, options, &a);
    size_t zero = 0;
    for (const Correspondence& m : a) zero += m.weight == 0.f;
    EXPECT_GT(zero, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, LatticeSearchTest, ::testing::Values("Box", "FkArm"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(CorrespondenceOptionsTest, Validation) {
  CorrespondenceOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error));
  options.max_distance = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_FALSE(error.empty());
  options = CorrespondenceOptions();
  options.window = -1;
  EXPECT_FALSE(options.IsValid(&error));
}

}  // namespace
}  // namespace edgefit
