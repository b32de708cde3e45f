// Malformed input: every case fails with one line that names the file (and
// the line for text formats) and the problem; nothing crashes or throws.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "edgefit/core/atomic_file.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/ptx.h"
#include "io/io_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

constexpr char kPtxHeader[] =
    "2\n3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
constexpr char kPtxPoints[] =
    "1.000000 0.000000 0.000000 0.5\n1.000000 0.000000 0.100000 0.5\n1.000000 0.000000 0.200000 0.5\n"
    "1.000000 0.100000 0.000000 0.5\n1.000000 0.100000 0.100000 0.5\n1.000000 0.100000 0.200000 0.5\n";

std::string Ptx(const std::string& points) { return std::string(kPtxHeader) + points; }

std::string ReplaceLine(std::string text, int line, const std::string& replacement) {
  size_t begin = 0;
  for (int i = 1; i < line; ++i) begin = text.find('\n', begin) + 1;
  const size_t end = text.find('\n', begin);
  return text.replace(begin, end - begin, replacement);
}

// A little-endian uint32, as PCD's binary_compressed sizes are written.
std::string U32(uint32_t v) {
  std::string bytes(4, '\0');
  for (size_t i = 0; i < 4; ++i) bytes[i] = static_cast<char>((v >> (8 * i)) & 255u);
  return bytes;
}

struct BadCase {
  const char* name;
  const char* extension;
  std::string content;
  std::string expected;  // substring of the message after "<file>: "
};

std::vector<BadCase> Cases() {
  const std::string good_ptx = Ptx(kPtxPoints);
  const std::string pcd_header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\n";
  const std::string ply_header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                 "property float y\nproperty float z\nend_header\n";
  return {
      {"PtxEmpty", "ptx", "", "no scans (empty file)"},
      {"PtxOnlyBlankLines", "ptx", "\n  \n\n", "no scans"},
      {"PtxNonNumericSize", "ptx", ReplaceLine(good_ptx, 1, "two"), "line 1: expected a positive integer"},
      {"PtxZeroRows", "ptx", ReplaceLine(good_ptx, 2, "0"), "line 2: expected a positive integer"},
      {"PtxHeaderCut", "ptx", "2\n3\n0 0 0\n1 0 0\n", "line 5: file ends inside a scan header"},
      {"PtxShortPositionLine", "ptx", ReplaceLine(good_ptx, 3, "0 0"), "line 3: expected 3 numbers"},
      {"PtxNanInMatrix", "ptx", ReplaceLine(good_ptx, 8, "0 nan 0 0"), "line 8: non-finite number"},
      {"PtxInfInMatrix", "ptx", ReplaceLine(good_ptx, 10, "inf 0 0 1"), "line 10: non-finite number"},
      {"PtxNonRigidMatrix", "ptx", ReplaceLine(good_ptx, 7, "2 0 0 0"), "line 10: the 4x4 matrix is not a rigid"},
      {"PtxMatrixLastColumn", "ptx", ReplaceLine(good_ptx, 10, "0 0 0 2"), "must end in columns 0 0 0 1"},
      {"PtxTruncatedPoints", "ptx", good_ptx.substr(0, good_ptx.size() - 62), "line 15: scan 1 ends after 4 of 6"},
      {"PtxHugeHeader", "ptx", ReplaceLine(good_ptx, 1, "2000000000"), "header promises"},
      {"PtxNonNumericToken", "ptx", ReplaceLine(good_ptx, 13, "1.0 abc 0.1 0.5"), "line 13: expected 4 numbers"},
      {"PtxNanCoordinate", "ptx", ReplaceLine(good_ptx, 14, "nan 0 0.1 0.5"), "line 14: non-finite coordinate"},
      {"PtxInfCoordinate", "ptx", ReplaceLine(good_ptx, 16, "1 inf 0.1 0.5"), "line 16: non-finite coordinate"},
      {"PtxFiveNumbers", "ptx", ReplaceLine(good_ptx, 12, "1 0 0.1 0.5 7"), "line 12: more than 4 numbers"},
      {"PtxWrongFirstCount", "ptx", ReplaceLine(good_ptx, 11, "1 0 0 0.5 9"), "line 11: expected 4 (x y z intensity) or 7"},
      {"PtxThreeNumbers", "ptx", ReplaceLine(good_ptx, 12, "1 0 0"), "line 12: expected 4 numbers"},
      {"PtxBadColour", "ptx", Ptx("1 0 0 0.5 1 2 3\n1 0 0.1 0.5 1 2 300\n1 0 0.2 0.5 1 2 3\n"
                                 "1 0.1 0 0.5 1 2 3\n1 0.1 0.1 0.5 1 2 3\n1 0.1 0.2 0.5 1 2 3\n"),
       "line 12: expected colour integers 0..255"},
      {"PtxNoValidPoints", "ptx", Ptx("0 0 0 0.5\n0 0 0 0.5\n0 0 0 0.5\n0 0 0 0.5\n0 0 0 0.5\n0 0 0 0.5\n"),
       "scan 1: no valid points"},
      {"PtxTooSparseForLattice", "ptx", good_ptx, "scan 1: too few valid points to estimate the lattice"},
      {"PtxSecondScanBroken", "ptx", good_ptx + "2\n3\n0 0 0\n", "line 20: file ends inside a scan header"},
      {"PcdCompressedNoSizes", "pcd", pcd_header + "DATA binary_compressed\n" + U32(24),
       "ends before its two sizes"},
      {"PcdCompressedWrongSize", "pcd", pcd_header + "DATA binary_compressed\n" + U32(10) + U32(99),
       "holds 99 bytes, but 2 points of 12 bytes need 24"},
      {"PcdCompressedTruncated", "pcd",
       pcd_header + "DATA binary_compressed\n" + U32(50) + U32(24) + std::string(10, '\0'),
       "promises 50 compressed bytes but only 10 follow"},
      {"PcdCompressedHugeClaim", "pcd",
       "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 100000\nHEIGHT 1000\nDATA binary_compressed\n" +
           U32(2) + U32(1200000000) + std::string(2, '\0'),
       "corrupt sizes"},
      // A back reference before any byte was written.
      {"PcdCompressedCorrupt", "pcd",
       pcd_header + "DATA binary_compressed\n" + U32(3) + U32(24) + "\xe0\xff\xff",
       "corrupt LZF stream"},
      {"PcdNoData", "pcd", pcd_header, "no DATA line"},
      {"PcdEmpty", "pcd", "", "no DATA line"},
      {"PcdNoZ", "pcd", "FIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2\n", "FIELDS must include x y z"},
      {"PcdSizeMismatch", "pcd", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3\n",
       "disagree in length"},
      {"PcdPointsMismatch", "pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 3\nDATA ascii\n",
       "POINTS 3 != WIDTH x HEIGHT 2"},
      {"PcdBadType", "pcd", "FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3\n",
       "unsupported TYPE/SIZE"},
      {"PcdAsciiToken", "pcd", pcd_header + "DATA ascii\n1 2 3\n1 x 3\n", "line 11: expected 3 numbers"},
      {"PcdAsciiTruncated", "pcd", pcd_header + "DATA ascii\n1 2 3\n", "line 11: file ends after 1 of 2"},
      {"PcdAsciiInf", "pcd", pcd_header + "DATA ascii\n1 2 3\n1 inf 3\n", "line 11: infinite coordinate"},
      {"PcdBinaryTruncated", "pcd", pcd_header + "DATA binary\n" + std::string(20, '\0'), "file truncated"},
      {"PcdHugeCount", "pcd",
       "FIELDS x y z rgb\nSIZE 4 4 4 2\nTYPE F F F U\nCOUNT 555500000001 1 1 2\nWIDTH 1\nHEIGHT 1\n"
       "DATA binary\n",
       "field x: SIZE 4 x COUNT 555500000001 makes a point record larger than 1 MiB"},
      {"PcdHugeSize", "pcd", "FIELDS x y z\nSIZE 4294967300 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n",
       "field x: SIZE 4294967300 x COUNT 1"},
      {"PcdUnknownKey", "pcd", "FIELDS x y z\nCOLOR 1\n", "line 2: unknown PCD header key"},
      {"PcdAllNan", "pcd", pcd_header + "DATA ascii\nnan nan nan\nnan nan nan\n", "no valid points"},
      {"PlyNotPly", "ply", "solid cube\n", "not a PLY file"},
      {"PlyEmpty", "ply", "", "not a PLY file"},
      {"PlyNoEndHeader", "ply", "ply\nformat ascii 1.0\nelement vertex 2\n", "no end_header"},
      {"PlyNoVertex", "ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n", "no vertex element"},
      {"PlyBadFormat", "ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "line 2: unknown format"},
      {"PlyAsciiToken", "ply", ply_header + "1 2 3\n1 2 three\n", "line 9: expected 3 numbers"},
      {"PlyAsciiTruncated", "ply", ply_header + "1 2 3\n", "line 9: file ends after 1 of 2"},
      {"PlyNan", "ply", ply_header + "1 2 3\nnan 2 3\n", "vertex 2: non-finite"},
      {"PlyBinaryTruncated", "ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n" + std::string(30, '\0'),
       "file truncated"},
      {"UnknownExtension", "xyz", "1 2 3\n", "unknown scan format"},
  };
}

class BadInputTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInputTest, FailsWithOneClearLine) {
  const BadCase& c = GetParam();
  const std::string path = testing::TempPath(std::string(c.name) + "." + c.extension);
  ASSERT_TRUE(WriteStringAtomically(path, c.content).ok());
  ScanSet scans;
  const Status status = ReadScans(path, ReadOptions(), &scans);
  std::remove(path.c_str());
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message().rfind(path + ": ", 0), 0u) << status.message();
  EXPECT_NE(status.message().find(c.expected), std::string::npos) << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos) << status.message();
  EXPECT_TRUE(scans.scans.empty());
}

INSTANTIATE_TEST_SUITE_P(Files, BadInputTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return info.param.name; });

TEST(BadInputTest, MissingFile) {
  ScanSet scans;
  const Status status = ReadScans("/nonexistent/dir/scan.ptx", ReadOptions(), &scans);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), "/nonexistent/dir/scan.ptx: cannot open: No such file or directory");
}

TEST(BadInputTest, GoodPtxParsesWithoutLattice) {
  // The fixture itself is fine: only the lattice needs more points.
  ReadOptions options;
  options.estimate_lattice = false;
  const std::string path = testing::TempPath("good.ptx");
  ASSERT_TRUE(WriteStringAtomically(path, Ptx(kPtxPoints)).ok());
  ScanSet scans;
  const Status status = ReadScans(path, options, &scans);
  std::remove(path.c_str());
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(scans.scans[0].CountValid(), 6u);
}

TEST(BadInputTest, FailedWriteLeavesNoFile) {
  ScanSet scans;  // no scans: PTX refuses
  const std::string path = testing::TempPath("nothing.ptx");
  EXPECT_FALSE(WriteScans(path, scans, WriteOptions()).ok());
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_FALSE(WriteScans(testing::TempPath("x.las"), scans, WriteOptions()).ok());
}

// Every prefix of a valid file either parses or fails with a message naming
// the file; run under -DEDGEFIT_SANITIZE=ON this also proves no read past the end.
TEST(BadInputTest, EveryTruncationFailsCleanly) {
  testing::SyntheticScanOptions o;
  o.rows = 12;
  o.cols = 20;
  o.color = true;
  o.missing_fraction = 0.2;
  ScanSet set;
  set.scans.push_back(testing::MakeSyntheticScan(testing::RoomScene(), o));
  struct Format {
    std::string path;
    bool binary;
  };
  const std::vector<Format> formats = {{testing::TempPath("t.ptx"), false}, {testing::TempPath("t.pcd"), false},
                                       {testing::TempPath("tb.pcd"), true}, {testing::TempPath("t.ply"), false},
                                       {testing::TempPath("tb.ply"), true}};
  for (const Format& format : formats) {
    WriteOptions write;
    write.binary = format.binary;
    ASSERT_TRUE(WriteScans(format.path, set, write).ok());
    std::string content;
    ASSERT_TRUE(ReadFileToString(format.path, &content).ok());
    std::remove(format.path.c_str());
    const char* ext = format.path.c_str() + format.path.size() - 3;
    ReadOptions options;
    options.lattice.min_valid_points = 10;
    size_t failures = 0;
    for (size_t n = 0; n < content.size(); n += (n < 400 || n + 100 > content.size()) ? 1 : 7) {
      const std::string prefix = content.substr(0, n);  // own buffer: ASan sees overreads
      ScanSet scans;
      const Status status = std::string(ext) == "ptx" ? ParsePtx(prefix, "cut", options, &scans)
                            : std::string(ext) == "pcd" ? ParsePcd(prefix, "cut", options, &scans)
                                                        : ParsePly(prefix, "cut", options, &scans);
      if (!status.ok()) {
        ++failures;
        EXPECT_EQ(status.message().rfind("cut: ", 0), 0u) << status.message();
        EXPECT_TRUE(scans.scans.empty());
      }
    }
    EXPECT_GT(failures, 100u) << format.path;
  }
}

}  // namespace
}  // namespace edgefit
