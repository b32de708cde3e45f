// A depth camera's frame: the ROS camera_info YAML (both layouts), the
// 16-bit depth PNG with it, the organized PCD in the camera's optical frame
// read with its camera, a point list put back on its grid; each bad input
// fails with one line naming the file.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "edgefit/io/camera_info.h"
#include "edgefit/io/pcd.h"
#include "edgefit/io/ply.h"
#include "edgefit/io/scan_io.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

class DepthFrameTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("edgefit_depth_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // A bit_depth grey PNG of width x height holding `pixels` row by row.
  std::string WritePng(const std::string& name, int width, int height,
                       const std::vector<uint16_t>& pixels, int bit_depth = 16) {
    const std::string path = (dir_ / name).string();
    std::FILE* file = std::fopen(path.c_str(), "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, bit_depth, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<uint8_t> row(static_cast<size_t>(width) * 2);
    for (int v = 0; v < height; ++v) {
      for (int u = 0; u < width; ++u) {
        const uint16_t d = pixels[static_cast<size_t>(v * width + u)];
        if (bit_depth == 16) {
          row[2 * u] = static_cast<uint8_t>(d >> 8);  // big endian
          row[2 * u + 1] = static_cast<uint8_t>(d & 0xff);
        } else {
          row[u] = static_cast<uint8_t>(d);
        }
      }
      png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return path;
  }

  fs::path dir_;
};

// sensor_msgs/CameraInfo as ROS 2 prints it (lower case keys).
const char kRos2Info[] =
    "height: 4\nwidth: 6\ndistortion_model: plumb_bob\nd: [0.0, 0.0, 0.0, 0.0, 0.0]\n"
    "k: [500.0, 0.0, 2.5, 0.0, 480.0, 1.5, 0.0, 0.0, 1.0]\n"
    "p: [500.0, 0.0, 2.5, 0.0, 0.0, 480.0, 1.5, 0.0, 0.0, 0.0, 1.0, 0.0]\n";

TEST_F(DepthFrameTest, CameraInfoInBothLayouts) {
  CameraInfo info;
  ASSERT_TRUE(ReadCameraInfo(Write("ros2.yaml", kRos2Info), &info).ok());
  EXPECT_EQ(info.width, 6);
  EXPECT_EQ(info.height, 4);
  EXPECT_EQ(info.camera.fx, 500.0);
  EXPECT_EQ(info.camera.fy, 480.0);
  EXPECT_EQ(info.camera.cx, 2.5);
  EXPECT_EQ(info.camera.cy, 1.5);
  EXPECT_FALSE(info.camera.HasDistortion());
  const std::string calibration =
      "image_width: 640\nimage_height: 480\ncamera_name: depth\ncamera_matrix:\n  rows: 3\n"
      "  cols: 3\n  data: [580.5, 0, 315.3, 0, 576.6, 247.5, 0, 0, 1]\n"
      "distortion_model: plumb_bob\ndistortion_coefficients:\n  rows: 1\n  cols: 5\n"
      "  data: [0.13, -0.31, 0.0023, 0.0031, 0.0]\n";
  ASSERT_TRUE(ReadCameraInfo(Write("calibration.yaml", calibration), &info).ok());
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.camera.cy, 247.5);
  EXPECT_TRUE(info.camera.HasDistortion());
  EXPECT_EQ(info.camera.distortion[3], 0.0031);  // p2
}

TEST_F(DepthFrameTest, BadCameraInfoNamesTheFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"missing.yaml", ""},  // not written
      {"garbage.yaml", "k: [1, 2\n"},
      {"no_size.yaml", "k: [500, 0, 2, 0, 500, 2, 0, 0, 1]\n"},
      {"short_k.yaml", "width: 4\nheight: 4\nk: [500, 0, 2]\n"},
      {"zero_f.yaml", "width: 4\nheight: 4\nk: [0, 0, 2, 0, 500, 2, 0, 0, 1]\n"},
      {"fisheye.yaml",
       "width: 4\nheight: 4\nk: [500, 0, 2, 0, 500, 2, 0, 0, 1]\ndistortion_model: equidistant\n"
       "d: [0.1, 0.01, 0, 0]\n"}};
  for (const auto& [name, text] : cases) {
    const std::string path = text.empty() ? (dir_ / name).string() : Write(name, text);
    CameraInfo info;
    const Status status = ReadCameraInfo(path, &info);
    EXPECT_FALSE(status.ok()) << name;
    EXPECT_EQ(status.message().rfind(path + ": ", 0), 0u) << status.message();
    EXPECT_EQ(status.message().find('\n'), std::string::npos) << status.message();
    EXPECT_TRUE(info.empty()) << name;
  }
}

TEST_F(DepthFrameTest, DepthPngBecomesAnOrganizedFrameOnItsCamera) {
  ReadOptions options;
  ASSERT_TRUE(ReadCameraInfo(Write("camera_info.yaml", kRos2Info), &options.camera).ok());
  std::vector<uint16_t> depth(24, 2000);  // 2 m
  depth[0] = 0;                           // no measurement
  depth[1 * 6 + 4] = 1234;                // row 1, column 4
  ScanSet scans;
  ASSERT_TRUE(ReadScans(WritePng("frame.png", 6, 4, depth), options, &scans).ok());
  ASSERT_EQ(scans.scans.size(), 1u);
  const OrganizedScan& scan = scans.scans[0];
  EXPECT_EQ(scan.rows(), 4);
  EXPECT_EQ(scan.cols(), 6);
  EXPECT_EQ(scan.CountValid(), 23u);
  EXPECT_FALSE(scan.IsValid(scan.Index(0, 0)));
  const Eigen::Vector3f p = scan.point_scanner(scan.Index(1, 4));
  EXPECT_NEAR(p.z(), 1.234, 1e-6);
  EXPECT_NEAR(p.x(), (4 - 2.5) / 500.0 * 1.234, 1e-6);
  EXPECT_NEAR(p.y(), (1 - 1.5) / 480.0 * 1.234, 1e-6);
  EXPECT_EQ(scan.lattice().model(), ScanLattice::Model::kProjective);
  int row, col;
  ASSERT_TRUE(scan.lattice().ProjectToCell(p.cast<double>(), &row, &col));
  EXPECT_EQ(row, 1);
  EXPECT_EQ(col, 4);
  EXPECT_TRUE(scan.T_world_scanner().isApprox(Pose::Identity()));
  EXPECT_EQ(scan.FileIndex(scan.Index(1, 4)), 1u * 6u + 4u);  // the PNG's row by row
}

TEST_F(DepthFrameTest, BadDepthPngsNameTheFile) {
  ReadOptions options;
  ASSERT_TRUE(ReadCameraInfo(Write("camera_info.yaml", kRos2Info), &options.camera).ok());
  const std::vector<uint16_t> depth(24, 1500);
  const std::vector<std::pair<std::string, ReadOptions>> cases = {
      {WritePng("eight_bit.png", 6, 4, std::vector<uint16_t>(24, 150), 8), options},
      {WritePng("other_size.png", 4, 6, depth), options},
      {WritePng("empty.png", 6, 4, std::vector<uint16_t>(24, 0)), options},
      {Write("truncated.png", "\x89PNG\r\n\x1a\n"), options},
      {WritePng("no_camera.png", 6, 4, depth), ReadOptions()}};
  for (const auto& [path, read_options] : cases) {
    ScanSet scans;
    const Status status = ReadScans(path, read_options, &scans);
    EXPECT_FALSE(status.ok()) << path;
    EXPECT_EQ(status.message().rfind(path + ": ", 0), 0u) << status.message();
    EXPECT_TRUE(scans.scans.empty()) << path;
  }
}

TEST_F(DepthFrameTest, OrganizedPcdTakesItsCamerasLattice) {
  ReadOptions with_camera;
  ASSERT_TRUE(ReadCameraInfo(Write("camera_info.yaml", kRos2Info), &with_camera.camera).ok());
  OrganizedScan frame(4, 6);
  frame.set_file_order(OrganizedScan::FileOrder::kRowMajor);
  for (int v = 0; v < 4; ++v) {
    for (int u = 0; u < 6; ++u) {
      const Eigen::Vector3d p = (2.0 + 0.1 * u) * with_camera.camera.camera.Ray(u, v);
      frame.SetPoint(frame.Index(v, u), p.cast<float>(), 0.0f);
    }
  }
  const std::string path = (dir_ / "frame.pcd").string();
  ASSERT_TRUE(WritePcd(path, frame, WriteOptions()).ok());
  ScanSet scans;
  ASSERT_TRUE(ReadScans(path, with_camera, &scans).ok());
  const ScanLattice& lattice = scans.scans[0].lattice();
  ASSERT_EQ(lattice.model(), ScanLattice::Model::kProjective);
  EXPECT_EQ(lattice.camera().fx, 500.0);
  // Another camera's size: refused, naming both.
  ReadOptions other = with_camera;
  other.camera.width = 8;
  ScanSet none;
  const Status status = ReadScans(path, other, &none);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("camera_info.yaml"), std::string::npos) << status.message();
}

// A frame written as a point list (the pixels without a depth dropped, as a
// RealSense .ply or Open3D's clouds are): read with its camera, every point
// is back on its pixel; read with other intrinsics, refused.
TEST_F(DepthFrameTest, PointListReturnsToItsCamerasGrid) {
  for (const double k1 : {0.0, -0.2}) {  // a pinhole, and a lens with barrel distortion
    ReadOptions with_camera;
    ASSERT_TRUE(ReadCameraInfo(Write("camera_info.yaml", kRos2Info), &with_camera.camera).ok());
    with_camera.camera.camera.distortion[0] = k1;
    OrganizedScan frame(4, 6);
    frame.set_file_order(OrganizedScan::FileOrder::kRowMajor);
    for (int v = 0; v < 4; ++v) {
      for (int u = 0; u < 6; ++u) {
        if (u == 2 && v == 1) continue;  // no depth there
        const Eigen::Vector3d p = (2.0 + 0.1 * u) * with_camera.camera.camera.Ray(u, v);
        frame.SetPoint(frame.Index(v, u), p.cast<float>(), 0.25f * u);
      }
    }
    ScanSet list;
    list.scans.push_back(frame);
    const std::string path = (dir_ / "frame.ply").string();
    ASSERT_TRUE(WritePly(path, list, WriteOptions()).ok());
    ScanSet scans;
    const Status status = ReadScans(path, with_camera, &scans);
    ASSERT_TRUE(status.ok()) << status.message();
    const OrganizedScan& grid = scans.scans[0];
    ASSERT_TRUE(grid.organized());
    ASSERT_EQ(grid.rows(), 4);
    ASSERT_EQ(grid.cols(), 6);
    EXPECT_EQ(grid.lattice().model(), ScanLattice::Model::kProjective);
    EXPECT_FALSE(grid.IsValid(grid.Index(1, 2)));
    for (int v = 0; v < 4; ++v) {
      for (int u = 0; u < 6; ++u) {
        const size_t i = frame.Index(v, u);
        if (!frame.IsValid(i)) continue;
        EXPECT_LT((grid.point_scanner(i) - frame.point_scanner(i)).norm(), 1e-6) << v << " " << u;
      }
    }
    ReadOptions other = with_camera;
    other.camera.camera.fx = 510.0;
    ScanSet none;
    const Status refused = ReadScans(path, other, &none);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.message().rfind(path + ": ", 0), 0u) << refused.message();
    EXPECT_NE(refused.message().find("not a frame of the camera"), std::string::npos);
  }
}

}  // namespace
}  // namespace edgefit
