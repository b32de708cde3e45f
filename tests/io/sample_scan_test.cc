// The bundled sample (assets/samples/two_scans.ptx) is what the generator
// makes today, and it loads with a sensible lattice.
#include <gtest/gtest.h>

#include <string>

#include "edgefit/io/scan_io.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

TEST(SampleScanTest, BundledSampleMatchesGenerator) {
  const std::string path = std::string(EDGEFIT_SOURCE_DIR) + "/assets/samples/two_scans.ptx";
  ScanSet loaded;
  const Status status = ReadScans(path, ReadOptions(), &loaded);
  ASSERT_TRUE(status.ok()) << status.message();
  const ScanSet expected = testing::MakeSampleScanSet();
  ASSERT_EQ(loaded.scans.size(), expected.scans.size());
  for (size_t s = 0; s < loaded.scans.size(); ++s) {
    const OrganizedScan& a = loaded.scans[s];
    const OrganizedScan& b = expected.scans[s];
    ASSERT_EQ(a.rows(), b.rows());
    ASSERT_EQ(a.cols(), b.cols());
    EXPECT_EQ(a.CountValid(), b.CountValid());
    EXPECT_TRUE(a.T_world_scanner().isApprox(b.T_world_scanner(), 1e-12));
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.IsValid(i), b.IsValid(i)) << "cell " << i;
      if (a.IsValid(i)) worst = std::max(worst, (a.point_scanner(i) - b.point_scanner(i)).cast<double>().norm());
    }
    EXPECT_LT(worst, 1e-5);
    // Full 360 degree scans at 1.2 degrees per column, 0.75 per row.
    EXPECT_TRUE(a.lattice().full_circle());
    EXPECT_NEAR(std::abs(a.lattice().col_step()), 1.2 * M_PI / 180.0, 1e-4);
    EXPECT_NEAR(std::abs(a.lattice().row_step()), 0.75 * M_PI / 180.0, 1e-4);
  }
}

}  // namespace
}  // namespace edgefit
