// Interop with CloudCompare: a PTX written by edgefit, loaded and exported to
// ASCII by CloudCompare's command line, gives the same world points (the 4x4
// matrix convention) and intensities. Skipped without /usr/bin/CloudCompare.
// (CloudCompare as packaged in Debian 12 has no PCD plugin, so PCD is not checked.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "edgefit/io/ptx.h"
#include "io/io_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

constexpr char kCloudCompare[] = "/usr/bin/CloudCompare";

TEST(CloudCompareTest, PtxWorldPointsMatch) {
  if (::access(kCloudCompare, X_OK) != 0) GTEST_SKIP() << kCloudCompare << " not installed";
  testing::SyntheticScanOptions o;
  o.rows = 24;
  o.cols = 40;
  o.missing_fraction = 0.2;
  o.range_noise_m = 0.001;
  // A pose with all three rotations and a translation, so that a transposed
  // matrix convention would show.
  o.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(3.0, -1.0, 1.6), Eigen::Vector3d(0.05, -0.1, 2.0));
  ScanSet set;
  set.scans.push_back(testing::MakeSyntheticScan(testing::RoomScene(), o));
  const std::string ptx = testing::TempPath("cc.ptx");
  const std::string asc = testing::TempPath("cc.asc");
  ASSERT_TRUE(WritePtx(ptx, set).ok());
  // -SILENT: no dialogs; -NO_TIMESTAMP + -SAVE_CLOUDS FILE: a fixed output name.
  const std::string command = std::string("QT_QPA_PLATFORM=offscreen ") + kCloudCompare +
                              " -SILENT -NO_TIMESTAMP -O " + ptx +
                              " -C_EXPORT_FMT ASC -PREC 8 -SEP SPACE -SAVE_CLOUDS FILE " + asc +
                              " > " + asc + ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(asc);
  ASSERT_TRUE(in.good()) << "CloudCompare wrote no " << asc;
  std::vector<Eigen::Vector4d> cc;  // x y z intensity
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    Eigen::Vector4d v;
    if (fields >> v[0] >> v[1] >> v[2] >> v[3]) cc.push_back(v);
  }
  std::remove(ptx.c_str());
  std::remove(asc.c_str());
  std::remove((asc + ".log").c_str());
  const OrganizedScan& scan = set.scans[0];
  ASSERT_EQ(cc.size(), scan.CountValid());
  // Match each CloudCompare point to its nearest edgefit world point.
  size_t matched = 0;
  for (const Eigen::Vector4d& v : cc) {
    double best = 1e9;
    float intensity = -1.0f;
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const double d = (scan.PointWorld(i) - v.head<3>()).norm();
      if (d < best) {
        best = d;
        intensity = scan.intensity(i);
      }
    }
    EXPECT_LT(best, 1e-4);
    EXPECT_NEAR(v[3], intensity, 1e-6);
    matched += best < 1e-4 ? 1 : 0;
  }
  EXPECT_EQ(matched, scan.CountValid());
}

}  // namespace
}  // namespace edgefit
