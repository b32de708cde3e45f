#include "edgefit/scan/organized_scan.h"

#include <gtest/gtest.h>

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

// Chunks with no valid cell are let go for the shared empty one: they read
// missing, cost no cells, and a write there takes a chunk of its own again
// (the other scans' empty chunks stay empty).
TEST(OrganizedScanTest, EmptyChunksAreShared) {
  const size_t rows = OrganizedScan::kChunkCells;
  OrganizedScan scan(static_cast<int>(rows), 4);  // four chunks, the second one valid
  scan.DropIntensity();
  for (size_t i = rows; i < 2 * rows; ++i) scan.SetPoint(i, Eigen::Vector3f(1.0f, 2.0f, 3.0f), 0.0f);
  const double before = scan.BytesPerCell();
  scan.ShareEmptyChunks();
  EXPECT_LT(scan.BytesPerCell(), 0.3 * before);
  EXPECT_EQ(scan.CountValid(), rows);
  EXPECT_EQ(scan.point_scanner(rows), Eigen::Vector3f(1.0f, 2.0f, 3.0f));
  EXPECT_FALSE(scan.IsValid(0));
  EXPECT_FALSE(scan.IsValid(4 * rows - 1));
  OrganizedScan other = scan;
  scan.SetMissing(0);  // already missing: stays shared
  EXPECT_LT(scan.BytesPerCell(), 0.3 * before);
  scan.SetPoint(5, Eigen::Vector3f(4.0f, 5.0f, 6.0f), 0.0f);
  EXPECT_EQ(scan.point_scanner(5), Eigen::Vector3f(4.0f, 5.0f, 6.0f));
  EXPECT_FALSE(other.IsValid(5));
  EXPECT_FALSE(scan.IsValid(4));
  EXPECT_EQ(scan.CountValid(), rows + 1);
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
  EXPECT_EQ(scan.CountValid(), scan.size());
}

// SetMissingWhere on a copy: a chunk with nothing dropped stays shared with
// the original, one with everything dropped becomes the shared empty one,
// only a chunk with some dropped is copied; the original keeps every cell.
TEST(OrganizedScanTest, SetMissingWhereCopiesOnlyTheBoundary) {
  const size_t rows = OrganizedScan::kChunkCells;
  OrganizedScan original(static_cast<int>(rows), 3);  // three chunks
  original.DropIntensity();
  for (size_t i = 0; i < original.size(); ++i) {
    original.SetPoint(i, Eigen::Vector3f(1.0f, 0.0f, static_cast<float>(i)), 0.0f);
  }
  OrganizedScan crop = original;
  const float first_kept = static_cast<float>(rows + rows / 2);
  crop.SetMissingWhere([&](const Eigen::Vector3f& p) { return p.z() < first_kept; });
  EXPECT_EQ(crop.CountValid(), rows + rows / 2);
  EXPECT_EQ(original.CountValid(), original.size());
  EXPECT_FALSE(crop.IsValid(rows + rows / 2 - 1));
  EXPECT_TRUE(crop.IsValid(rows + rows / 2));
  EXPECT_EQ(&crop.point_scanner(2 * rows), &original.point_scanner(2 * rows));  // shared
  EXPECT_NE(&crop.point_scanner(rows), &original.point_scanner(rows));          // copied
  // 2 chunks of 3 held (the empty one counts as nothing), 1 of them its own.
  EXPECT_LT(crop.BytesPerCell(), 0.7 * original.BytesPerCell());
}

}  // namespace
}  // namespace edgefit
