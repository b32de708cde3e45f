// The world report's page: every part with its poses, the waypoints' notes
// and collision points, the plots; inconsistent input one line, no file.
#include "edgefit/report/world_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "edgefit/core/atomic_file.h"
#include "edgefit/model/primitive_meshes.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

class WorldReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!CheckThreeJs(kDebianThreeJsDir).ok()) GTEST_SKIP() << "libjs-three not installed";
    dir_ = fs::temp_directory_path() / ("world_report_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    // An arm's link that moves over two waypoints, far from the origin as
    // survey coordinates are, and a floor.
    WorldReportPart link;
    link.name = "robot_link_2";
    link.machine = "robot";
    link.mesh = MakeBoxMesh(Eigen::Vector3d(0.2, 0.2, 1.0));
    Pose a = Pose::Identity(), b = Pose::Identity();
    a.translation() = Eigen::Vector3d(5000.0, 3000.0, 1.0);
    b.translation() = Eigen::Vector3d(5000.5, 3000.0, 0.2);
    link.T_world_part = {a, b};
    WorldReportPart floor;
    floor.kind = WorldReportPart::Kind::kBackground;
    floor.name = "background";
    floor.mesh = MakeBoxMesh(Eigen::Vector3d(4.0, 4.0, 0.02));
    Pose T_floor = Pose::Identity();
    T_floor.translation() = Eigen::Vector3d(5000.0, 3000.0, -0.01);
    floor.T_world_part = {T_floor};
    report_.title = "a <robot> & its floor";
    report_.machine = "robot";
    report_.parts = {link, floor};
    report_.waypoint_notes = {"free", "COLLIDES: robot_link_2 with background"};
    report_.collision_points = {Eigen::Vector3d::Constant(std::nan("")),
                                Eigen::Vector3d(5000.5, 3000.0, 0.0)};
    Chart chart;
    chart.title = "Clearance along the trajectory";
    chart.series = {{"to the background", {1, 2}, {500, 0}, false}};
    report_.charts = {chart};
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
  WorldReport report_;
};

TEST_F(WorldReportTest, ThePageHoldsEveryPartAndWaypoint) {
  ASSERT_TRUE(WriteWorldReport(report_, Path("w.html")).ok());
  std::string page;
  ASSERT_TRUE(ReadFileToString(Path("w.html"), &page).ok());
  EXPECT_NE(page.find("<title>a &lt;robot&gt; &amp; its floor</title>"), std::string::npos);
  EXPECT_NE(page.find("\"name\":\"robot_link_2\""), std::string::npos);
  EXPECT_NE(page.find("\"kind\":\"background\""), std::string::npos);
  EXPECT_NE(page.find("COLLIDES: robot_link_2 with background"), std::string::npos);
  EXPECT_NE(page.find("<svg"), std::string::npos);
  EXPECT_NE(page.find("<div id=\"status\">loading</div>"), std::string::npos);
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);  // three.js embedded
}

TEST_F(WorldReportTest, InconsistentInputIsOneLineAndNoFile) {
  WorldReport three_poses = report_;
  three_poses.parts[0].T_world_part.push_back(Pose::Identity());
  const Status poses = WriteWorldReport(three_poses, Path("w.html"));
  EXPECT_EQ(poses.message(), "world report: part 'robot_link_2' has 3 poses for 2 waypoints");
  WorldReport one_point = report_;
  one_point.collision_points.pop_back();
  EXPECT_FALSE(WriteWorldReport(one_point, Path("w.html")).ok());
  WorldReport none = report_;
  none.waypoint_notes.clear();
  none.collision_points.clear();
  EXPECT_EQ(WriteWorldReport(none, Path("w.html")).message(), "world report: no waypoints");
  WorldReport no_three = report_;
  no_three.three_js_dir = Path("absent");
  EXPECT_NE(WriteWorldReport(no_three, Path("w.html")).message().find("absent/three.min.js"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(Path("w.html")));
}

}  // namespace
}  // namespace edgefit
