#include <gtest/gtest.h>
#include <lzf.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "edgefit/core/atomic_file.h"
#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/scan_io.h"
#include "io/io_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

using testing::ExpectSameScan;
using testing::TempPath;

OrganizedScan Sample(bool color) {
  testing::SyntheticScanOptions o;
  o.rows = 30;
  o.cols = 50;
  o.missing_fraction = 0.2;
  o.range_noise_m = 0.001;
  o.color = color;
  o.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(1.0, -2.0, 1.5), Eigen::Vector3d(0.02, 0.01, 0.7));
  return testing::MakeSyntheticScan(testing::RoomScene(), o);
}

class PcdRoundTripTest : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(PcdRoundTripTest, ReadWriteRead) {
  const auto [binary, color] = GetParam();
  ScanSet original;
  original.scans.push_back(Sample(color));
  WriteOptions write;
  write.binary = binary;
  const std::string path = TempPath(std::string("rt_") + (binary ? "b" : "a") + (color ? "c" : "") + ".pcd");
  ASSERT_TRUE(WriteScans(path, original, write).ok());
  ScanSet first;
  const Status status = ReadScans(path, ReadOptions(), &first);
  ASSERT_TRUE(status.ok()) << status.message();
  const OrganizedScan& scan = first.scans[0];
  EXPECT_TRUE(scan.organized());
  EXPECT_EQ(scan.file_order(), OrganizedScan::FileOrder::kRowMajor);
  OrganizedScan expected = original.scans[0];
  expected.set_lattice(scan.lattice());
  ExpectSameScan(expected, scan, 1e-12);  // pose through a quaternion
  // World points are the viewpoint applied to the stored scanner-frame points.
  for (size_t i = 0; i < scan.size(); ++i) {
    if (scan.IsValid(i)) {
      EXPECT_LT((scan.PointWorld(i) - original.scans[0].PointWorld(i)).norm(), 1e-9);
    }
  }
  const std::string path2 = TempPath(std::string("rt2_") + (binary ? "b" : "a") + (color ? "c" : "") + ".pcd");
  ASSERT_TRUE(WriteScans(path2, first, write).ok());
  ScanSet second;
  ASSERT_TRUE(ReadScans(path2, ReadOptions(), &second).ok());
  ExpectSameScan(first.scans[0], second.scans[0]);
  std::remove(path.c_str());
  std::remove(path2.c_str());
}

INSTANTIATE_TEST_SUITE_P(AsciiBinaryColour, PcdRoundTripTest,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) ? "Binary" : "Ascii") +
                                  (std::get<1>(info.param) ? "Rgb" : "NoRgb");
                         });

// A binary PCD rewritten as PCL's binary_compressed: each field's values for
// every point in turn, LZF-compressed after the compressed and uncompressed
// sizes (little endian).
std::string BinaryCompressed(const std::string& binary) {
  const size_t data = binary.find("DATA binary\n");
  const size_t payload = data + std::string("DATA binary\n").size();
  std::vector<size_t> bytes;  // per field: SIZE x COUNT
  auto numbers = [&](const char* key) {
    std::vector<size_t> v;
    const size_t line = binary.find(std::string("\n") + key + " ");
    if (line == std::string::npos || line > data) return v;
    const size_t begin = line + 2 + std::strlen(key);
    std::istringstream in(binary.substr(begin, binary.find('\n', begin) - begin));
    for (size_t x; in >> x;) v.push_back(x);
    return v;
  };
  const std::vector<size_t> sizes = numbers("SIZE"), counts = numbers("COUNT");
  size_t record = 0;
  for (size_t i = 0; i < sizes.size(); ++i) {
    bytes.push_back(sizes[i] * (counts.empty() ? 1 : counts[i]));
    record += bytes.back();
  }
  const size_t n = (binary.size() - payload) / record;
  std::string fields;
  for (size_t f = 0, offset = 0; f < bytes.size(); offset += bytes[f++]) {
    for (size_t p = 0; p < n; ++p) fields += binary.substr(payload + p * record + offset, bytes[f]);
  }
  std::string compressed(fields.size() + 64, '\0');
  const unsigned size = lzf_compress(fields.data(), static_cast<unsigned>(fields.size()),
                                     compressed.data(), static_cast<unsigned>(compressed.size()));
  EXPECT_GT(size, 0u);
  compressed.resize(size);
  std::string out = binary.substr(0, data) + "DATA binary_compressed\n";
  for (const uint32_t v : {static_cast<uint32_t>(size), static_cast<uint32_t>(fields.size())}) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 255u);
  }
  return out + compressed;
}

TEST(PcdTest, BinaryCompressedReadsAsBinary) {
  for (const bool color : {false, true}) {
    ScanSet original;
    original.scans.push_back(Sample(color));
    WriteOptions write;
    write.binary = true;
    const std::string path = TempPath(std::string("compressed_") + (color ? "c" : "") + ".pcd");
    ASSERT_TRUE(WriteScans(path, original, write).ok());
    std::string binary;
    ASSERT_TRUE(ReadFileToString(path, &binary).ok());
    std::remove(path.c_str());
    ScanSet plain, compressed;
    ASSERT_TRUE(ParsePcd(binary, "plain.pcd", ReadOptions(), &plain).ok());
    const std::string text = BinaryCompressed(binary);
    ASSERT_NE(text.find("DATA binary_compressed\n"), std::string::npos);
    const Status status = ParsePcd(text, "compressed.pcd", ReadOptions(), &compressed);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_TRUE(compressed.scans[0].organized());
    EXPECT_GT(compressed.scans[0].CountValid(), 0u);
    ExpectSameScan(plain.scans[0], compressed.scans[0]);
  }
}

TEST(PcdTest, ReadsPclStyleHeaderAndExtraFields) {
  // PCL writes rgb as a float field and prints its bits as an integer in ascii.
  const std::string text =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb normal_x curvature\nSIZE 4 4 4 4 4 8\n"
      "TYPE F F F F F F\nCOUNT 1 1 1 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS 3\nDATA ascii\n"
      "1 2 3 16711680 0 0.5\nnan nan nan 0 0 0\n0.5 0.25 -1 65280 1 2\n";
  ScanSet set;
  const Status status = ParsePcd(text, "pcl.pcd", ReadOptions(), &set);
  ASSERT_TRUE(status.ok()) << status.message();
  const OrganizedScan& scan = set.scans[0];
  EXPECT_FALSE(scan.organized());
  EXPECT_EQ(scan.size(), 3u);
  EXPECT_EQ(scan.CountValid(), 2u);
  EXPECT_TRUE(scan.PointWorld(0).isApprox(Eigen::Vector3d(2, 4, 6)));
  EXPECT_EQ(scan.color(0), (std::array<uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(scan.color(2), (std::array<uint8_t, 3>{0, 255, 0}));
  EXPECT_FLOAT_EQ(scan.intensity(0), 0.0f);
}

TEST(PcdTest, OrganizedIsWidthColumnsByHeightRowsRowMajor) {
  const std::string text =
      "FIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 3\nHEIGHT 2\nPOINTS 6\nDATA ascii\n"
      "1 0 0 1\n1 1 0 2\n1 2 0 3\n1 0 1 4\n1 1 1 5\n1 2 1 6\n";
  ReadOptions options;
  options.estimate_lattice = false;
  ScanSet set;
  ASSERT_TRUE(ParsePcd(text, "grid.pcd", options, &set).ok());
  const OrganizedScan& scan = set.scans[0];
  ASSERT_EQ(scan.rows(), 2);
  ASSERT_EQ(scan.cols(), 3);
  EXPECT_FLOAT_EQ(scan.intensity(scan.Index(0, 2)), 3.0f);
  EXPECT_FLOAT_EQ(scan.intensity(scan.Index(1, 0)), 4.0f);
  EXPECT_EQ(scan.FileIndex(scan.Index(1, 0)), 3u);
}

class PlyRoundTripTest : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(PlyRoundTripTest, ValidPointsInWorldCoordinates) {
  const auto [binary, color] = GetParam();
  ScanSet original;
  original.scans.push_back(Sample(color));
  WriteOptions write;
  write.binary = binary;
  const std::string path = TempPath(std::string("rt_") + (binary ? "b" : "a") + (color ? "c" : "") + ".ply");
  ASSERT_TRUE(WriteScans(path, original, write).ok());
  ScanSet first;
  const Status status = ReadScans(path, ReadOptions(), &first);
  ASSERT_TRUE(status.ok()) << status.message();
  const OrganizedScan& cloud = first.scans[0];
  EXPECT_FALSE(cloud.organized());
  EXPECT_FALSE(cloud.lattice().valid());
  EXPECT_TRUE(cloud.T_world_scanner().matrix().isIdentity());
  ASSERT_EQ(cloud.size(), original.scans[0].CountValid());
  EXPECT_EQ(cloud.has_color(), color);
  size_t k = 0;
  for (size_t i = 0; i < original.scans[0].size(); ++i) {
    if (!original.scans[0].IsValid(i)) continue;
    EXPECT_LT((cloud.PointWorld(k) - original.scans[0].PointWorld(i)).norm(), 1e-5);
    EXPECT_EQ(cloud.intensity(k), original.scans[0].intensity(i));
    if (color) {
      EXPECT_EQ(cloud.color(k), original.scans[0].color(i));
    }
    ++k;
  }
  const std::string path2 = TempPath(std::string("rt2_") + (binary ? "b" : "a") + (color ? "c" : "") + ".ply");
  ASSERT_TRUE(WriteScans(path2, first, write).ok());
  ScanSet second;
  ASSERT_TRUE(ReadScans(path2, ReadOptions(), &second).ok());
  ExpectSameScan(cloud, second.scans[0]);
  std::remove(path.c_str());
  std::remove(path2.c_str());
}

INSTANTIATE_TEST_SUITE_P(AsciiBinaryColour, PlyRoundTripTest,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) ? "Binary" : "Ascii") +
                                  (std::get<1>(info.param) ? "Rgb" : "NoRgb");
                         });

TEST(PlyTest, ReadsBigEndianAndSkipsFaces) {
  std::string text =
      "ply\nformat binary_big_endian 1.0\ncomment test\nelement vertex 2\nproperty double x\n"
      "property double y\nproperty double z\nproperty uchar scalar_Intensity\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  auto put_be = [&text](const void* p, size_t n) {
    const char* c = static_cast<const char*>(p);
    for (size_t i = n; i > 0; --i) text.push_back(c[i - 1]);  // host little endian in CI
  };
  for (double v : {1.0, 2.0, 3.0}) put_be(&v, 8);
  text.push_back(static_cast<char>(7));
  for (double v : {-1.0, 0.5, 0.25}) put_be(&v, 8);
  text.push_back(static_cast<char>(9));
  text += "\x03garbage-faces";
  ScanSet set;
  const Status status = ParsePly(text, "be.ply", ReadOptions(), &set);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(set.scans[0].size(), 2u);
  EXPECT_TRUE(set.scans[0].PointWorld(1).isApprox(Eigen::Vector3d(-1.0, 0.5, 0.25)));
  EXPECT_FLOAT_EQ(set.scans[0].intensity(0), 7.0f);
}

TEST(ScanIoTest, PcdHoldsExactlyOneScan) {
  ScanSet two;
  two.scans.push_back(Sample(false));
  two.scans.push_back(Sample(false));
  const Status status = WriteScans(TempPath("two.pcd"), two, WriteOptions());
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("one scan"), std::string::npos);
}

}  // namespace
}  // namespace edgefit
