// Mixed pixels at a known object's silhouette (MarkSilhouetteMixedPixels):
// a ramp of ranges from the object to the wall behind it is found, the wall
// itself and a surface sloping away beside the object are not, and cells
// already marked stay as they were.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "edgefit/scan/mixed_pixels.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace {

constexpr int kRows = 12, kCols = 40;

// Range of cell (row, col): the object (columns 0-19) at 2 m, a ramp of
// two mixed pixels, then the wall at 2.12 m; in rows 0-3 the wall slopes
// away by 10 mm per column.
double Range(int row, int col) {
  if (col < 20) return 2.0;
  if (col < 22) return 2.0 + 0.04 * (col - 19);
  return 2.12 + (row < 4 ? 0.01 * (col - 22) : 0.0);
}

ScanSet Grid() {
  OrganizedScan scan(kRows, kCols);
  for (int col = 0; col < kCols; ++col) {
    for (int row = 0; row < kRows; ++row) {
      const Eigen::Vector3f d = Eigen::Vector3f(1.0f, 0.002f * (col - 20), 0.002f * (row - 6)).normalized();
      scan.SetPoint(scan.Index(row, col), d * static_cast<float>(Range(row, col)), 1.0f);
    }
  }
  ScanSet scans;
  scans.scans.push_back(scan);
  return scans;
}

TEST(SilhouetteMixedPixelsTest, TheRampBesideTheObjectAndNothingBehindIt) {
  const ScanSet scans = Grid();
  const OrganizedScan& scan = scans.scans[0];
  std::vector<std::vector<uint8_t>> object(1, std::vector<uint8_t>(scan.size(), 0));
  for (int col = 0; col < 20; ++col) {
    for (int row = 0; row < kRows; ++row) object[0][scan.Index(row, col)] = 1;
  }
  std::vector<std::vector<uint8_t>> mixed(1, std::vector<uint8_t>(scan.size(), 0));
  mixed[0][scan.Index(6, 30)] = 1;  // marked before: stays, not counted
  const size_t added = MarkSilhouetteMixedPixels(scans, object, MixedPixelOptions(), 3, &mixed);
  // The ramp is found along the row and both diagonals through it: two
  // lines at least, which the grid's first and last two rows may lack.
  size_t ramp = 0;
  for (int col = 0; col < kCols; ++col) {
    for (int row = 0; row < kRows; ++row) {
      const bool marked = mixed[0][scan.Index(row, col)] != 0;
      if (col == 20 || col == 21) {
        ramp += marked;
        if (row >= 2 && row < kRows - 2) {
          EXPECT_TRUE(marked) << "row " << row << ", col " << col;
        }
      } else {
        EXPECT_EQ(marked, row == 6 && col == 30) << "row " << row << ", col " << col;
      }
    }
  }
  EXPECT_EQ(added, ramp);

  // Without the object, nothing.
  std::vector<std::vector<uint8_t>> none(1, std::vector<uint8_t>(scan.size(), 0));
  std::vector<std::vector<uint8_t>> unmarked(1, std::vector<uint8_t>(scan.size(), 0));
  EXPECT_EQ(MarkSilhouetteMixedPixels(scans, none, MixedPixelOptions(), 3, &unmarked), 0u);
}

}  // namespace
}  // namespace edgefit
