#include "edgefit/io/ptx.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>

#include "edgefit/core/angles.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/scan_io.h"
#include "io/io_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

using testing::ExpectSameScan;
using testing::MakeSyntheticScan;
using testing::SyntheticScanOptions;
using testing::TempPath;

TEST(PtxTest, RoundTripTwoScansWithColour) {
  ScanSet original;
  for (uint32_t seed : {1u, 2u}) {
    SyntheticScanOptions o = testing::SmallScanOptions(seed);
    o.color = true;
    if (seed == 2) {
      o.R_scanner_lattice =
          Eigen::AngleAxisd(2 * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
      o.T_world_scanner = PoseFromXyYaw(2.0, 1.0, -2.5);
    }
    original.scans.push_back(MakeSyntheticScan(testing::RoomScene(), o));
  }
  const std::string path = TempPath("round_trip.ptx");
  ASSERT_TRUE(WriteScans(path, original, WriteOptions()).ok());
  ScanSet first, second;
  const Status s1 = ReadScans(path, ReadOptions(), &first);
  ASSERT_TRUE(s1.ok()) << s1.message();
  ASSERT_EQ(first.scans.size(), 2u);
  EXPECT_EQ(first.sources[1], path);
  for (size_t s = 0; s < 2; ++s) {
    // The writer's lattice-free scans against the reader's: same cells and poses.
    OrganizedScan expected = original.scans[s];
    expected.set_lattice(first.scans[s].lattice());
    ExpectSameScan(expected, first.scans[s]);
    EXPECT_TRUE(first.scans[s].lattice().valid());
    EXPECT_EQ(first.scans[s].file_order(), OrganizedScan::FileOrder::kColumnMajor);
  }
  const std::string path2 = TempPath("round_trip2.ptx");
  ASSERT_TRUE(WriteScans(path2, first, WriteOptions()).ok());
  ASSERT_TRUE(ReadScans(path2, ReadOptions(), &second).ok());
  ASSERT_EQ(second.scans.size(), 2u);
  for (size_t s = 0; s < 2; ++s) ExpectSameScan(first.scans[s], second.scans[s]);
  // Same bytes the second time: the writer is deterministic and exact.
  std::string a, b;
  ASSERT_TRUE(ReadFileToString(path, &a).ok());
  ASSERT_TRUE(ReadFileToString(path2, &b).ok());
  EXPECT_EQ(a, b);
  std::remove(path.c_str());
  std::remove(path2.c_str());
}

TEST(PtxTest, WorldIsMatrixAppliedAndMissingIsZero) {
  // 2 columns x 2 rows; translation (10, 20, 30), 90 degrees about z: the
  // matrix lines hold the rotation's columns (row-vector convention).
  const std::string text =
      "2\n2\n10 20 30\n0 1 0\n-1 0 0\n0 0 1\n"
      "0 1 0 0\n-1 0 0 0\n0 0 1 0\n10 20 30 1\n"
      "1 0 0 0.5\n0 0 0 0.5\n1 0.1 0.2 0.25\n2 0 1 0.75\n";
  ReadOptions options;
  options.estimate_lattice = false;
  options.detect_ptx_layout = false;
  ScanSet set;
  const Status status = ParsePtx(text, "tiny.ptx", options, &set);
  ASSERT_TRUE(status.ok()) << status.message();
  const OrganizedScan& scan = set.scans[0];
  EXPECT_EQ(scan.rows(), 2);
  EXPECT_EQ(scan.cols(), 2);
  EXPECT_FALSE(scan.IsValid(1));
  EXPECT_EQ(scan.CountValid(), 3u);
  EXPECT_TRUE(scan.PointWorld(0).isApprox(Eigen::Vector3d(10, 21, 30), 1e-12));
  EXPECT_TRUE(scan.PointWorld(3).isApprox(Eigen::Vector3d(10, 22, 31), 1e-12));
  EXPECT_FLOAT_EQ(scan.intensity(2), 0.25f);
}

TEST(PtxTest, ToleratesCrLfTabsAndBareZeroMisses) {
  const std::string text =
      "2\r\n2\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n1 0 0 0\r\n0 1 0 0\r\n0 0 1 0\r\n"
      "0 0 0 1\r\n1\t0 0 0.5\r\n0 0 0\r\n+1 0.1 0.2 0.25\r\n2 0 1e0 0.75";  // no final newline
  ReadOptions options;
  options.estimate_lattice = false;
  ScanSet set;
  const Status status = ParsePtx(text, "crlf.ptx", options, &set);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(set.scans[0].CountValid(), 3u);
  EXPECT_FLOAT_EQ(set.scans[0].point_scanner(3).z(), 1.0f);
}

// Writes `scan` as PTX text with the header sizes in either order and the
// cells column by column or row by row.
std::string PtxText(const OrganizedScan& scan, bool header_rows_first, bool row_major) {
  std::string t = header_rows_first
                      ? std::to_string(scan.rows()) + "\n" + std::to_string(scan.cols()) + "\n"
                      : std::to_string(scan.cols()) + "\n" + std::to_string(scan.rows()) + "\n";
  t += "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  char buf[32];
  auto add = [&](float v) { t.append(buf, std::to_chars(buf, buf + 32, v).ptr); };
  const int outer = row_major ? scan.rows() : scan.cols(),
            inner = row_major ? scan.cols() : scan.rows();
  for (int o = 0; o < outer; ++o) {
    for (int k = 0; k < inner; ++k) {
      const size_t i = row_major ? scan.Index(o, k) : scan.Index(k, o);
      if (!scan.IsValid(i)) {
        t += "0 0 0 0\n";
        continue;
      }
      const Eigen::Vector3f& p = scan.point_scanner(i);
      add(p.x());
      t += ' ';
      add(p.y());
      t += ' ';
      add(p.z());
      t += ' ';
      add(scan.intensity(i));
      t += '\n';
    }
  }
  return t;
}

struct LayoutCase {
  const char* name;
  bool header_rows_first;
  bool row_major;
};

class PtxLayoutTest : public ::testing::TestWithParam<LayoutCase> {};

TEST_P(PtxLayoutTest, DetectsLayoutFromData) {
  for (bool reversed : {false, true}) {  // also: azimuth decreasing, rows top-down
    SyntheticScanOptions o = testing::SmallScanOptions(5);
    if (reversed) {
      o.azimuth_first = -o.azimuth_first;
      o.azimuth_step = -o.azimuth_step;
      o.elevation_first = 10 * kDeg;
      o.elevation_step = -o.elevation_step;
    }
    const OrganizedScan truth = MakeSyntheticScan(testing::RoomScene(), o);
    ScanSet set;
    const Status status =
        ParsePtx(PtxText(truth, GetParam().header_rows_first, GetParam().row_major), "layout.ptx",
                 ReadOptions(), &set);
    ASSERT_TRUE(status.ok()) << status.message();
    const OrganizedScan& scan = set.scans[0];
    EXPECT_EQ(scan.file_order(), GetParam().row_major ? OrganizedScan::FileOrder::kRowMajor
                                                      : OrganizedScan::FileOrder::kColumnMajor);
    OrganizedScan expected = truth;
    expected.set_lattice(scan.lattice());
    expected.set_T_world_scanner(scan.T_world_scanner());
    ExpectSameScan(expected, scan);
    // And the writer keeps the file order: read(write(scan)) == scan.
    const std::string path = TempPath(std::string(GetParam().name) + ".ptx");
    ASSERT_TRUE(WritePtx(path, set).ok());
    ScanSet again;
    ASSERT_TRUE(ReadPtx(path, ReadOptions(), &again).ok());
    EXPECT_EQ(again.scans[0].file_order(), scan.file_order());
    ExpectSameScan(scan, again.scans[0]);
    std::remove(path.c_str());
  }
}

INSTANTIATE_TEST_SUITE_P(FourLayouts, PtxLayoutTest,
                         ::testing::Values(LayoutCase{"ColumnsRowsColumnMajor", false, false},
                                           LayoutCase{"RowsColumnsColumnMajor", true, false},
                                           LayoutCase{"ColumnsRowsRowMajor", false, true},
                                           LayoutCase{"RowsColumnsRowMajor", true, true}),
                         [](const ::testing::TestParamInfo<LayoutCase>& info) {
                           return info.param.name;
                         });

TEST(PtxTest, LoadedScanFitsMemoryBudget) {
  for (bool color : {false, true}) {
    SyntheticScanOptions o = testing::SmallScanOptions(3);
    o.color = color;
    ScanSet set;
    set.scans.push_back(MakeSyntheticScan(testing::RoomScene(), o));
    const std::string path = TempPath("memory.ptx");
    ASSERT_TRUE(WritePtx(path, set).ok());
    ScanSet loaded;
    ASSERT_TRUE(ReadPtx(path, ReadOptions(), &loaded).ok());
    const double bytes = loaded.scans[0].BytesPerCell();
    EXPECT_LE(bytes, 40.0);
    EXPECT_GE(bytes, color ? 19.0 : 16.0);
    std::remove(path.c_str());
  }
}

// ReadOptions::intensity = false (a fit's read): the same points, no
// intensities held.
TEST(PtxTest, ReadWithoutIntensityKeepsThePoints) {
  ScanSet set;
  set.scans.push_back(MakeSyntheticScan(testing::RoomScene(), testing::SmallScanOptions(3)));
  const std::string path = TempPath("no_intensity.ptx");
  ASSERT_TRUE(WritePtx(path, set).ok());
  ScanSet with, without;
  ReadOptions options;
  ASSERT_TRUE(ReadScans(path, options, &with).ok());
  options.intensity = false;
  ASSERT_TRUE(ReadScans(path, options, &without).ok());
  const OrganizedScan& a = with.scans[0];
  const OrganizedScan& b = without.scans[0];
  ASSERT_EQ(a.size(), b.size());
  size_t lit = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.IsValid(i), b.IsValid(i));
    if (!a.IsValid(i)) continue;
    EXPECT_EQ(a.point_scanner(i), b.point_scanner(i));
    EXPECT_EQ(b.intensity(i), 0.0f);
    lit += a.intensity(i) > 0.0f ? 1 : 0;
  }
  EXPECT_GT(lit, 0u);
  EXPECT_LT(b.BytesPerCell(), a.BytesPerCell() - 3.0);
  std::remove(path.c_str());
}

TEST(PtxTest, WritePtxRefusesUnorganizedScans) {
  ScanSet set;
  set.scans.emplace_back(1, 10);
  set.scans[0].set_organized(false);
  const std::string path = TempPath("unorganized.ptx");
  const Status status = WritePtx(path, set);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("organized"), std::string::npos);
  std::string content;
  EXPECT_FALSE(ReadFileToString(path, &content).ok()) << "no file may be left behind";
}

// PDAL's PTX reader test files (../shared/data/scans/ptx; skipped without
// it): the scan with colour is read on its 71 x 15 grid, point for point;
// the others are no scanner's grids (1 to 15 points a scan, too few for a
// lattice) or carry a scaled matrix, and are refused with their reason.
TEST(PtxTest, PdalFiles) {
  const std::string dir = std::string(EDGEFIT_SHARED_DIR) + "/data/scans/ptx/";
  if (!std::ifstream(dir + "pdal_1.2-with-color.ptx").good()) {
    GTEST_SKIP() << "no " << dir << " (../shared absent)";
  }
  ScanSet scans;
  ASSERT_TRUE(ReadScans(dir + "pdal_1.2-with-color.ptx", ReadOptions(), &scans).ok());
  ASSERT_EQ(scans.scans.size(), 1u);
  const OrganizedScan& scan = scans.scans[0];
  EXPECT_EQ(scan.rows(), 71);
  EXPECT_EQ(scan.cols(), 15);
  EXPECT_EQ(scan.CountValid(), 1065u);
  ASSERT_TRUE(scan.has_color());
  // The file's first point: 637012.24 849028.31 431.66 0.034912 68 77 88,
  // identity pose (georeferenced: float keeps it to about 6 cm).
  bool found = false;
  for (size_t i = 0; i < scan.size() && !found; ++i) {
    const Eigen::Vector3d p = scan.PointWorld(i);
    found = (p - Eigen::Vector3d(637012.24, 849028.31, 431.66)).norm() < 0.1 &&
            scan.color(i) == std::array<uint8_t, 3>{68, 77, 88} &&
            std::abs(scan.intensity(i) - 0.034912f) < 1e-6f;
  }
  EXPECT_TRUE(found);

  const std::pair<const char*, const char*> refused[] = {
      {"pdal_no-color.ptx", "too few valid points to estimate the lattice"},
      {"pdal_complex-transform.ptx", "too few valid points to estimate the lattice"},
      {"pdal_multiple-and-transform.ptx", "not a rigid transform"}};
  for (const auto& [file, reason] : refused) {
    ScanSet other;
    const Status status = ReadScans(dir + file, ReadOptions(), &other);
    ASSERT_FALSE(status.ok()) << file;
    EXPECT_NE(status.message().find(file), std::string::npos) << status.message();
    EXPECT_NE(status.message().find(reason), std::string::npos) << status.message();
  }
}

}  // namespace
}  // namespace edgefit
