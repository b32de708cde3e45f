#include "edgefit/scan/organized_scan.h"

#include <gtest/gtest.h>

#include <thread>

#include "edgefit/core/pose.h"

namespace edgefit {
namespace {

OrganizedScan TwentyCellScan() {
  OrganizedScan scan(4, 5);
  for (size_t i = 0; i < scan.size(); ++i) {
    scan.SetPoint(i, Eigen::Vector3f(1.0f, 0.1f * static_cast<float>(i), 0.0f), 0.5f);
  }
  return scan;
}

// A copy that only moves its station shares the cells; one that writes a
// cell takes its own, and the original stays as it was.
TEST(OrganizedScanTest, CopiesShareCellsUntilOneWrites) {
  const OrganizedScan original = TwentyCellScan();
  OrganizedScan moved = original;
  moved.set_T_world_scanner(PoseFromXyzRpy({1.0, 2.0, 3.0}, {0.0, 0.0, 0.5}));
  EXPECT_EQ(&moved.point_scanner(0), &original.point_scanner(0));
  EXPECT_TRUE(original.T_world_scanner().isApprox(Pose::Identity()));

  OrganizedScan cut = original;
  cut.SetMissing(3);
  EXPECT_NE(&cut.point_scanner(0), &original.point_scanner(0));
  EXPECT_FALSE(cut.IsValid(3));
  EXPECT_TRUE(original.IsValid(3));
  EXPECT_TRUE(moved.IsValid(3));
  EXPECT_EQ(cut.CountValid(), original.CountValid() - 1);

  OrganizedScan coloured = original;
  coloured.SetColor(2, {1, 2, 3});
  EXPECT_TRUE(coloured.has_color());
  EXPECT_FALSE(original.has_color());
}

// A copy that sets a cell missing takes only that cell's chunk as its own:
// the coverings left out of a scan cost their chunks, not the scan.
TEST(OrganizedScanTest, AWriteCopiesOnlyItsChunk) {
  const size_t rows = OrganizedScan::kChunkCells / 2;
  OrganizedScan original(static_cast<int>(rows), 8);  // four chunks
  for (size_t i = 0; i < original.size(); ++i) {
    original.SetPoint(i, Eigen::Vector3f(1.0f, 0.0f, static_cast<float>(i)), 0.25f);
  }
  OrganizedScan cut = original;
  const size_t last = original.size() - 1;
  cut.SetMissing(last);
  EXPECT_FALSE(cut.IsValid(last));
  EXPECT_TRUE(original.IsValid(last));
  EXPECT_EQ(&cut.point_scanner(0), &original.point_scanner(0));
  EXPECT_NE(&cut.point_scanner(last - 1), &original.point_scanner(last - 1));
  EXPECT_EQ(cut.point_scanner(last - 1), original.point_scanner(last - 1));
  EXPECT_EQ(cut.intensity(last - 1), 0.25f);
  EXPECT_EQ(cut.CountValid(), original.size() - 1);
}

// DropIntensity frees the intensities; points are still written and read.
TEST(OrganizedScanTest, ADroppedIntensityReadsZero) {
  OrganizedScan scan = TwentyCellScan();
  const double with = scan.BytesPerCell();
  scan.DropIntensity();
  EXPECT_EQ(scan.intensity(1), 0.0f);
  scan.SetPoint(1, Eigen::Vector3f(2.0f, 0.0f, 0.0f), 0.75f);
  EXPECT_EQ(scan.point_scanner(1), Eigen::Vector3f(2.0f, 0.0f, 0.0f));
  EXPECT_EQ(scan.intensity(1), 0.0f);
  EXPECT_LT(scan.BytesPerCell(), with);
  scan.Detach();
  EXPECT_EQ(scan.CountValid(), scan.size());
}

// After Detach, threads may write distinct cells of a copy.
TEST(OrganizedScanTest, ADetachedCopyIsWrittenByThreads) {
  const OrganizedScan original = TwentyCellScan();
  OrganizedScan copy = original;
  copy.Detach();
  auto cut_every_fourth_from = [&copy](size_t first) {
    for (size_t i = first; i < copy.size(); i += 4) copy.SetMissing(i);
  };
  std::thread a(cut_every_fourth_from, 0), b(cut_every_fourth_from, 2);
  a.join();
  b.join();
  EXPECT_EQ(copy.CountValid(), original.size() / 2);
  EXPECT_EQ(original.CountValid(), original.size());
}

}  // namespace
}  // namespace edgefit
