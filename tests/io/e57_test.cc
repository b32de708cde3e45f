#include "edgefit/io/e57.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "edgefit/core/atomic_file.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/scan/lattice_estimation.h"
#include "io/io_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

using testing::ExpectSameScan;
using testing::MakeSyntheticScan;
using testing::SyntheticScanOptions;
using testing::TempPath;


const std::string kE57Dir = std::string(EDGEFIT_SHARED_DIR) + "/data/scans/e57/";

bool HaveSharedScans() { return std::ifstream(kE57Dir + "bunnyDouble.e57").good(); }

#define SKIP_WITHOUT_SHARED_SCANS() \
  if (!HaveSharedScans()) GTEST_SKIP() << "no " << kE57Dir << " (../shared absent)"


ScanSet TwoScans() {
  ScanSet set;
  set.scans.push_back(MakeSyntheticScan(testing::DefaultScene(), testing::SmallScanOptions(1, true)));
  SyntheticScanOptions second = testing::SmallScanOptions(2);
  second.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(-2.0, 1.0, 1.5), Eigen::Vector3d(0, 0, -2.5));
  set.scans.push_back(MakeSyntheticScan(testing::DefaultScene(), second));
  set.sources = {"a", "b"};
  return set;
}

// The valid points of `scan` as a 1 x N unorganized cloud.
OrganizedScan Unorganized(const OrganizedScan& scan) {
  OrganizedScan cloud(1, static_cast<int>(scan.CountValid()));
  cloud.set_organized(false);
  cloud.set_T_world_scanner(scan.T_world_scanner());
  size_t k = 0;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (scan.IsValid(i)) cloud.SetPoint(k++, scan.point_scanner(i), scan.intensity(i));
  }
  return cloud;
}

std::vector<Eigen::Vector3d> WorldPoints(const OrganizedScan& scan) {
  std::vector<Eigen::Vector3d> points;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (scan.IsValid(i)) points.push_back(scan.PointWorld(i));
  }
  return points;
}

std::string Bytes(const std::string& path) {
  std::string content;
  EXPECT_TRUE(ReadFileToString(path, &content).ok()) << path;
  return content;
}

TEST(E57Test, RoundTripOrganizedScansKeepsPointsGridPoseAndColour) {
  const ScanSet set = TwoScans();
  const std::string path = TempPath("two.e57");
  ASSERT_TRUE(WriteScans(path, set, WriteOptions()).ok());
  ScanSet read;
  const Status status = ReadScans(path, ReadOptions(), &read);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(read.scans.size(), 2u);
  EXPECT_EQ(read.sources[1], path);
  ScanSet expected = set;
  for (OrganizedScan& scan : expected.scans) {  // the reader estimates the lattice
    ScanLattice lattice;
    ASSERT_TRUE(EstimateLattice(scan, ReadOptions().lattice, &lattice).ok());
    scan.set_lattice(lattice);
  }
  for (size_t s = 0; s < 2; ++s) ExpectSameScan(expected.scans[s], read.scans[s], 1e-12);
  std::remove(path.c_str());
}

TEST(E57Test, RoundTripUnorganizedCloud) {
  ScanSet set;
  set.scans.push_back(Unorganized(TwoScans().scans[0]));
  const std::string path = TempPath("cloud.e57");
  ASSERT_TRUE(WriteE57(path, set).ok());
  ScanSet read;
  ASSERT_TRUE(ReadE57(path, ReadOptions(), &read).ok());
  ASSERT_EQ(read.scans.size(), 1u);
  EXPECT_FALSE(read.scans[0].organized());
  EXPECT_FALSE(read.scans[0].lattice().valid());
  ExpectSameScan(set.scans[0], read.scans[0]);
  std::remove(path.c_str());
}

TEST(E57Test, SameScansGiveTheSameBytesAndMemoryReadEqualsFileRead) {
  const ScanSet set = TwoScans();
  const std::string a = TempPath("a.e57"), b = TempPath("b.e57");
  ASSERT_TRUE(WriteE57(a, set).ok());
  ASSERT_TRUE(WriteE57(b, set).ok());
  const std::string bytes = Bytes(a);
  EXPECT_EQ(bytes, Bytes(b));
  EXPECT_EQ(bytes.size() % 1024, 0u);
  ScanSet from_file, from_memory;
  ASSERT_TRUE(ReadE57(a, ReadOptions(), &from_file).ok());
  ASSERT_TRUE(ParseE57(bytes, "mem", ReadOptions(), &from_memory).ok());
  ASSERT_EQ(from_file.scans.size(), from_memory.scans.size());
  for (size_t s = 0; s < from_file.scans.size(); ++s) ExpectSameScan(from_file.scans[s], from_memory.scans[s]);
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST(E57Test, DamagedFilesFailNamingTheProblem) {
  const std::string path = TempPath("damaged.e57");
  ASSERT_TRUE(WriteE57(path, TwoScans()).ok());
  const std::string good = Bytes(path);
  const auto message = [](const std::string& content) {
    ScanSet scans;
    const Status status = ParseE57(content, "f.e57", ReadOptions(), &scans);
    EXPECT_TRUE(scans.scans.empty());
    return status.ok() ? std::string("ok") : status.message();
  };
  std::string flipped = good;
  flipped[5000] = static_cast<char>(flipped[5000] ^ 0x10);
  EXPECT_EQ(message(flipped), "f.e57: page 4 (bytes 4096-5119) fails its CRC-32C checksum (file damaged)");
  EXPECT_NE(message(good.substr(0, good.size() - 1024)).find("the header says"), std::string::npos);
  EXPECT_NE(message(good.substr(0, good.size() - 10)).find("not a whole number of 1024-byte E57 pages"),
            std::string::npos);
  EXPECT_EQ(message(""), "f.e57: empty file");
  std::string not_e57(2048, 'x');
  EXPECT_NE(message(not_e57).find("f.e57: page 0"), std::string::npos);  // checksum first
  std::remove(path.c_str());
}

TEST(E57Test, RealOrganizedScanOfAPump) {
  SKIP_WITHOUT_SHARED_SCANS();
  ScanSet scans;
  const Status status = ReadScans(kE57Dir + "pumpAVisualReferenceImage.e57", ReadOptions(), &scans);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(scans.scans.size(), 1u);
  const OrganizedScan& scan = scans.scans[0];
  EXPECT_TRUE(scan.organized());
  EXPECT_EQ(scan.rows(), 1074);  // indexBounds: rows 0..1073, columns 0..344
  EXPECT_EQ(scan.cols(), 345);
  EXPECT_EQ(scan.CountValid(), 155201u);
  EXPECT_TRUE(scan.has_color());
  ASSERT_TRUE(scan.lattice().valid());
  // The file's cartesianBounds and sphericalBounds (rangeMinimum, rangeMaximum).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  double r_lo = 1e9, r_hi = 0;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (!scan.IsValid(i)) continue;
    const Eigen::Vector3d p = scan.point_scanner(i).cast<double>();
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    r_lo = std::min(r_lo, p.norm()), r_hi = std::max(r_hi, p.norm());
  }
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(-2.903764, -5.301103, -1.899705), 1e-6)) << lo.transpose();
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(1.721604, -0.792647, 1.843003), 1e-6)) << hi.transpose();
  EXPECT_NEAR(r_lo, 1.983619, 1e-5);
  EXPECT_NEAR(r_hi, 5.429336, 1e-5);
  // Rows run along elevation, 1074 rows over the file's 72.5 degrees.
  EXPECT_NEAR(std::abs(scan.lattice().elevation(1073) - scan.lattice().elevation(0)),
              0.48098946878 + 0.78503207256, 0.01);
}

TEST(E57Test, LibE57ReferenceFilesInFloatAndScaledIntegerAgree) {
  SKIP_WITHOUT_SHARED_SCANS();
  ScanSet doubles, ints;
  ASSERT_TRUE(ReadE57(kE57Dir + "bunnyDouble.e57", ReadOptions(), &doubles).ok());
  ASSERT_TRUE(ReadE57(kE57Dir + "bunnyInt32.e57", ReadOptions(), &ints).ok());
  const std::vector<Eigen::Vector3d> a = WorldPoints(doubles.scans[0]), b = WorldPoints(ints.scans[0]);
  ASSERT_EQ(a.size(), 30571u);
  ASSERT_EQ(b.size(), a.size());
  double worst = 0.0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, (a[i] - b[i]).cwiseAbs().maxCoeff());
    lo = lo.cwiseMin(a[i]), hi = hi.cwiseMax(a[i]);
  }
  EXPECT_LT(worst, 1.5e-6);  // the scaled integers' 1 um step, in float
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(-0.094689, 0.040011, -0.061873), 1e-6)) << lo.transpose();
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(0.061009, 0.187321, 0.058799), 1e-6)) << hi.transpose();

  ScanSet cube_f, cube_d;
  ASSERT_TRUE(ReadE57(kE57Dir + "ColouredCubeFloat.e57", ReadOptions(), &cube_f).ok());
  ASSERT_TRUE(ReadE57(kE57Dir + "ColouredCubeDouble.e57", ReadOptions(), &cube_d).ok());
  ASSERT_EQ(cube_f.scans[0].size(), 7680u);
  ExpectSameScan(cube_f.scans[0], cube_d.scans[0]);
}

TEST(E57Test, ThirdPartyFilesWithSeveralScansAndSixteenBitColour) {
  SKIP_WITHOUT_SHARED_SCANS();
  ScanSet two, merged;
  ASSERT_TRUE(ReadE57(kE57Dir + "pdal_A_B.e57", ReadOptions(), &two).ok());
  ASSERT_TRUE(ReadE57(kE57Dir + "pdal_A_merged_B.e57", ReadOptions(), &merged).ok());
  ASSERT_EQ(two.scans.size(), 2u);
  EXPECT_EQ(two.scans[0].CountValid(), 2u);
  EXPECT_EQ(two.scans[1].CountValid(), 4u);
  std::vector<Eigen::Vector3d> separate = WorldPoints(two.scans[0]), together = WorldPoints(merged.scans[0]);
  for (const auto& p : WorldPoints(two.scans[1])) separate.push_back(p);
  ASSERT_EQ(together.size(), separate.size());
  for (const auto& p : separate) {
    EXPECT_TRUE(std::any_of(together.begin(), together.end(), [&](const Eigen::Vector3d& q) {
      return (p - q).norm() < 1e-5;
    })) << p.transpose();
  }
  ScanSet colour;  // las2e57: colour 0..65535, returnIndex on an unorganized cloud
  ASSERT_TRUE(ReadE57(kE57Dir + "ColourRepresentation.e57", ReadOptions(), &colour).ok());
  EXPECT_EQ(colour.scans[0].CountValid(), 153u);
  EXPECT_TRUE(colour.scans[0].has_color());
}

TEST(E57Test, BrokenReferenceFilesFailWithTheirReason) {
  SKIP_WITHOUT_SHARED_SCANS();
  const struct {
    const char* file;
    const char* reason;
  } kCases[] = {
      {"bad-crc.e57", "fails its CRC-32C checksum"},
      {"empty.e57", "no 3D data"},
      {"PinholeImageWithDistortionParameters.e57", "no 3D data"},
      {"InvalidCVHeader.e57", "no CompressedVector section header"},
      {"ZeroPoints.e57", "no valid points"},
      {"ZeroPointsInvalid.e57", "no CompressedVector section header"},
  };
  for (const auto& c : kCases) {
    ScanSet scans;
    const Status status = ReadScans(kE57Dir + c.file, ReadOptions(), &scans);
    EXPECT_FALSE(status.ok()) << c.file;
    EXPECT_EQ(status.message().rfind(kE57Dir + c.file + ": ", 0), 0u) << status.message();
    EXPECT_NE(status.message().find(c.reason), std::string::npos) << status.message();
    EXPECT_TRUE(scans.scans.empty());
  }
}

}  // namespace
}  // namespace edgefit
