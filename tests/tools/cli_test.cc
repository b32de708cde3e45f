// The edgefit command's contract (DESIGN.md): exit 0 on success, 2 on bad
// input with exactly one line on stderr that names the file and the problem.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
namespace fs = std::filesystem;

TEST_F(CliTest, HelpListsCommands) {
  const RunResult r = Run("help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("info"), std::string::npos);
  const RunResult h = Run("info --help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("--scan"), std::string::npos);
  EXPECT_NE(h.out.find("--urdf"), std::string::npos);
}

TEST_F(CliTest, UsageErrorsAreBadInput) {
  ExpectBadInput("frobnicate", "unknown command 'frobnicate'");
  ExpectBadInput("info --scan=x.ptx --w_high=3", "unknown flag --w_high");
  ExpectBadInput("info --json=maybe --scan=x.ptx", "--json");
  ExpectBadInput("info", "exactly one of --scan or --urdf");
  ExpectBadInput("info --scan", "--scan needs a value");
}

TEST_F(CliTest, MissingScanFile) {
  ExpectBadInput("info --scan=" + (dir_ / "nope.ptx").string(), "nope.ptx");
}

TEST_F(CliTest, UnknownScanExtension) {
  const std::string path = Write("scan.xyz", "1 2 3\n");
  ExpectBadInput("info --scan=" + path, "scan.xyz");
}

TEST_F(CliTest, EmptyScanFile) { ExpectBadInput("info --scan=" + Write("empty.ptx", ""), "empty.ptx"); }

constexpr char kPtxHeader[] =
    "2\n2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

TEST_F(CliTest, MalformedPtx) {
  const std::string path = Write("bad.ptx", std::string(kPtxHeader) +
                                                "1 0 0 0.5\n1 0.01 0 0.5\n1 abc 0 0.5\n"
                                                "1 0.01 0.01 0.5\n");
  ExpectBadInput("info --scan=" + path, "bad.ptx");
}

TEST_F(CliTest, TruncatedPtx) {
  const std::string path = Write("trunc.ptx", std::string(kPtxHeader) + "1 0 0 0.5\n1 0.01 0 0.5\n");
  ExpectBadInput("info --scan=" + path, "trunc.ptx");
}

TEST_F(CliTest, NanInPtx) {
  const std::string path = Write("nan.ptx", std::string(kPtxHeader) +
                                                "1 0 0 0.5\nnan 0.01 0 0.5\n1 0 0.01 0.5\n"
                                                "1 0.01 0.01 0.5\n");
  ExpectBadInput("info --scan=" + path, "nan.ptx");
}

TEST_F(CliTest, MalformedPcd) {
  const std::string path =
      Write("bad.pcd", "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                       "COUNT 1 1 1\nWIDTH 2\nHEIGHT 2\nPOINTS 4\nDATA ascii\n1 2 3\n4 5\n");
  ExpectBadInput("info --scan=" + path, "bad.pcd");
}

TEST_F(CliTest, MalformedPly) {
  const std::string path = Write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                            "property float x\nproperty float y\n"
                                            "property float z\nend_header\n1 2 3\n4 5 6\n");
  ExpectBadInput("info --scan=" + path, "bad.ply");
}

TEST_F(CliTest, UrdfThatDoesNotParse) {
  const std::string path = Write("broken.urdf", "<robot name='r'><link name='a'></robot");
  ExpectBadInput("info --urdf=" + path, "broken.urdf");
}

TEST_F(CliTest, MissingMeshNamesThePathsTried) {
  const std::string path = Write(
      "nomesh.urdf",
      "<robot name='r'><link name='a'><visual><geometry><mesh filename='meshes/gone.stl'/>"
      "</geometry></visual></link></robot>");
  ExpectBadInput("info --urdf=" + path, "gone.stl");
}

TEST_F(CliTest, UnknownJointType) {
  const std::string path = Write(
      "joint.urdf",
      "<robot name='r'><link name='a'/><link name='b'/><joint name='j' type='spherical'>"
      "<parent link='a'/><child link='b'/></joint></robot>");
  ExpectBadInput("info --urdf=" + path, "spherical");
}

TEST_F(CliTest, AttachToUnknownLink) {
  const std::string model = std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf";
  ExpectBadInput("info --urdf=" + model + " --attach=" + model + "@no_such_link", "no_such_link");
}

TEST_F(CliTest, ScanInfoJson) {
  const std::string sample = std::string(EDGEFIT_SOURCE_DIR) + "/assets/samples/two_scans.ptx";
  const RunResult r = Run("info --json --scan=" + sample);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["scans"].size(), 2u);
  size_t valid = 0;
  for (const auto& s : j["scans"]) {
    EXPECT_GT(s["rows"].get<int>(), 10);
    EXPECT_GT(s["cols"].get<int>(), 10);
    EXPECT_GT(s["valid"].get<size_t>(), 0u);
    EXPECT_LE(s["valid"].get<int>(), s["rows"].get<int>() * s["cols"].get<int>());
    ASSERT_FALSE(s["lattice"].is_null());
    EXPECT_GT(std::abs(s["lattice"]["azimuth_step_deg"].get<double>()), 0.0);
    EXPECT_GT(std::abs(s["lattice"]["elevation_step_deg"].get<double>()), 0.0);
    valid += s["valid"].get<size_t>();
  }
  EXPECT_EQ(j["total_valid"].get<size_t>(), valid);
}

// A real depth camera's frame (../shared/data/real; skips without it): the
// organized PCD's lattice is the camera's projective one, estimated from its
// points as its camera_info gives it; the 16-bit depth PNG holds the same
// frame with --camera_info, and without it is refused in one line.
TEST_F(CliTest, ScanInfoOfARealDepthFrame) {
  const std::string set = std::string(EDGEFIT_SHARED_DIR) + "/data/real/lbr_med7_zed2i";
  if (!fs::exists(set + "/frames/000.pcd")) GTEST_SKIP() << "no " << set;
  const RunResult pcd = Run("info --json --scan=" + set + "/frames/000.pcd");
  ASSERT_EQ(pcd.exit_code, 0) << pcd.err;
  const nlohmann::json l = nlohmann::json::parse(pcd.out)["scans"][0]["lattice"];
  ASSERT_EQ(l["model"], "projective") << l.dump();
  EXPECT_NEAR(l["fx"].get<double>(), 534.6265, 0.01);  // camera_info.yaml
  EXPECT_NEAR(l["fy"].get<double>(), 534.6265, 0.01);
  EXPECT_NEAR(l["cx"].get<double>(), 478.0846, 0.01);
  EXPECT_NEAR(l["cy"].get<double>(), 260.9944, 0.01);
  const RunResult png = Run("info --json --scan=" + set + "/frames/000_depth.png --camera_info=" +
                            set + "/camera_info.yaml");
  ASSERT_EQ(png.exit_code, 0) << png.err;
  const nlohmann::json p = nlohmann::json::parse(png.out)["scans"][0];
  EXPECT_EQ(p["valid"], nlohmann::json::parse(pcd.out)["scans"][0]["valid"]);
  EXPECT_EQ(p["lattice"]["fx"].get<double>(), 534.6265258789062);
  ExpectBadInput("info --scan=" + set + "/frames/000_depth.png", "000_depth.png");
}

TEST_F(CliTest, ModelInfoJson) {
  const std::string model = std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf";
  const RunResult r = Run("info --json --urdf=" + model);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["links"].size(), 2u);
  ASSERT_GT(j["joints"].size(), 1u);
  for (const auto& joint : j["joints"]) {
    EXPECT_TRUE(joint.contains("name"));
    EXPECT_TRUE(joint.contains("type"));
    EXPECT_TRUE(joint.contains("lower"));
    EXPECT_TRUE(joint.contains("upper"));
  }
  EXPECT_FALSE(j["zero_pose_bbox"].is_null());
}

TEST_F(CliTest, RealRobotWithAttachedWeldGun) {
  const std::string robots = std::string(EDGEFIT_SHARED_DIR) + "/robots";
  const std::string kuka = robots + "/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf";
  const std::string gun = robots + "/weld_gun_x16005_botrail/weld_gun_x16005_botrail.urdf";
  if (!fs::exists(kuka) || !fs::exists(gun)) GTEST_SKIP() << "no ../shared/robots";
  const RunResult r = Run("info --json --urdf=" + kuka + " --attach=" + gun + "@tool0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  std::set<std::string> names;
  for (const auto& link : j["links"]) names.insert(link["name"].get<std::string>());
  EXPECT_TRUE(names.count("link_6"));
  EXPECT_TRUE(names.count("electrode_arm"));
  EXPECT_TRUE(names.count("tcp"));
  int revolute = 0;
  for (const auto& joint : j["joints"]) revolute += joint["type"] == "revolute";
  EXPECT_EQ(revolute, 7);  // six robot axes and the gun's electrode arm
  // The gun adds about 1 m of reach beyond the flange.
  const nlohmann::json alone = nlohmann::json::parse(Run("info --json --urdf=" + kuka).out);
  const double reach_with = j["zero_pose_bbox"]["max"][0].get<double>();
  const double reach_alone = alone["zero_pose_bbox"]["max"][0].get<double>();
  EXPECT_GT(reach_with, reach_alone + 0.2);
}

}  // namespace
