// edgefit world from result.json files: the world folder written whole, a
// machine per result named as asked; bad input one line, exit 2, nothing
// written.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
namespace fs = std::filesystem;

// A result.json as edgefit fit writes it, of the bundled robot.
std::string Result(const std::string& joint_2, bool ok, const std::string& x = "3") {
  return std::string("{\"inputs\": {\"urdf\": \"") + EDGEFIT_SOURCE_DIR +
         "/assets/robot/robot.urdf\", \"attach\": [], \"scan\": []},\n"
         "\"joints\": {\"joint_1\": 0.1, \"joint_2\": " + joint_2 +
         ", \"joint_3\": 0.3, \"joint_4\": 0.4, \"joint_5\": 0.5, \"joint_6\": 0.6, "
         "\"balancer_cylinder_joint\": 0, \"balancer_piston_joint\": 0},\n"
         "\"base\": {\"T_world_base\": [[0, -1, 0, " + x + "], [1, 0, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]},\n"
         "\"quality\": {\"ok\": " + (ok ? "true" : "false") + ", \"message\": \"joint_6 is ambiguous\"}}\n";
}

TEST_F(CliTest, WorldFromTwoResults) {
  const std::string left = Write("left.json", Result("0.2", true));
  const std::string right = Write("right.json", Result("-0.2", false, "6"));
  const RunResult r = Run("world --result=" + left + "," + right + " --name=left,right --out_dir=" +
                          Path("world"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("right.json, 10 links, prefixed right_, its points within 8.0 mm, 0 riding on it off its CAD (the fit "
                       "said not ok: joint_6 is ambiguous; placed as fitted)"),
            std::string::npos)
      << r.out;
  const std::string urdf = Slurp(Path("world/cell.urdf"));
  EXPECT_NE(urdf.find("<joint name=\"world_to_left\" type=\"fixed\">"), std::string::npos);
  EXPECT_NE(urdf.find("<joint name=\"right_joint_2\" type=\"revolute\">"), std::string::npos);
  EXPECT_NE(urdf.find("<origin xyz=\"3 1 0\""), std::string::npos);  // the fitted base
  const std::string states = Slurp(Path("world/joint_states.yaml"));
  EXPECT_NE(states.find("left_joint_2, left_joint_3"), std::string::npos) << states;
  EXPECT_NE(states.find("0.1, 0.2, 0.3"), std::string::npos) << states;
  EXPECT_NE(states.find("0.1, -0.2, 0.3"), std::string::npos) << states;
  EXPECT_TRUE(fs::exists(Path("world/meshes/left_link_1.stl")));
  EXPECT_NE(r.out.find("background: none"), std::string::npos) << r.out;  // no scans named
  EXPECT_FALSE(fs::exists(Path("world/background.bt")));
  EXPECT_NE(Slurp(Path("world/cell.srdf")).find("<group_state name=\"as_scanned\" group=\"right\">"),
            std::string::npos);

  // Bad input: one line, exit 2, the folder as it was.
  const std::string before = Slurp(Path("world/cell.urdf"));
  ExpectBadInput("world --result=" + left + " --name=a,b --out_dir=" + Path("world"),
                 "--name gives 2 names for 1 results");
  ExpectBadInput("world --result=" + left + "," + left + " --out_dir=" + Path("world"),
                 "left.json: machine name 'left' is given twice");
  ExpectBadInput("world --result=" + left + " --name=a/b --out_dir=" + Path("world"),
                 "machine name 'a/b' may hold only letters, digits, '_' and '-'");
  Write("no_joint.json", Result("0.2", true).replace(Result("0.2", true).find("\"joint_3\""), 16, ""));
  ExpectBadInput("world --result=" + Path("no_joint.json") + " --out_dir=" + Path("world"),
                 "no_joint.json: joint 'joint_3'");
  ExpectBadInput("world --result=" + Path("absent.json") + " --out_dir=" + Path("world"), "absent.json");
  ExpectBadInput("world --result=" + left, "--out_dir is required");
  EXPECT_EQ(Slurp(Path("world/cell.urdf")), before);

  // edgefit clearance in that world: left's trajectory, in JSON.
  Write("traj.csv", "# left leans over\njoint_2,joint_3\n0.2,0.3\n0.5,0.3\n");
  const RunResult c = Run("clearance --world=" + Path("world") + " --machine=left --trajectory=" +
                          Path("traj.csv") + " --json");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const nlohmann::json out = nlohmann::json::parse(c.out);
  ASSERT_EQ(out["waypoints"].size(), 2u);
  for (const nlohmann::json& w : out["waypoints"]) {
    EXPECT_TRUE(w["distance_to_background"].is_null());  // the world has no background
    EXPECT_GT(w["distance_to_machines"].get<double>(), 0.5);  // right stands 3 m away
    EXPECT_TRUE(w["self_distance"].is_number());
    EXPECT_FALSE(w["colliding"].get<bool>());
  }
  EXPECT_TRUE(out["first_collision"].is_null());
  ExpectBadInput("clearance --world=" + Path("world") + " --joints=joint_2=0.1",
                 "2 machines (left, right): name the one to check");
  ExpectBadInput("clearance --world=" + Path("world") + " --machine=middle",
                 "no machine 'middle' (the world holds: left, right)");
  ExpectBadInput("clearance --world=" + Path("world") + " --machine=left --joints=joint_2=9",
                 "--joints: joint 'joint_2': 9 is outside its limits");
  Write("bad.csv", "joint_2,joint_3\n0.2,nan\n");
  ExpectBadInput("clearance --world=" + Path("world") + " --machine=left --trajectory=" + Path("bad.csv"),
                 "bad.csv:2: 'nan' is not a finite number");
  Write("short.csv", "joint_2,joint_3\n0.2\n");
  ExpectBadInput("clearance --world=" + Path("world") + " --machine=left --trajectory=" + Path("short.csv"),
                 "short.csv:2: 1 values for 2 joints in the header");
  ExpectBadInput("clearance --world=" + Path("absent"), "absent: not a folder");
}

// edgefit clearance --out_report: the page shows the world (the wall
// scanned before the arm, the arm at each waypoint) and opens in a browser.
TEST_F(CliTest, ClearanceReportShowsTheWorld) {
  const std::string result = Write("arm.json", Result("0.2", true));
  std::string wall = "ply\nformat ascii 1.0\nelement vertex 20000\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n";
  for (int i = 0; i < 200; ++i) {
    for (int k = 0; k < 100; ++k) wall += "4.6 " + std::to_string(-1.0 + 0.02 * i) + " " + std::to_string(0.02 * k) + "\n";
  }
  const std::string scan = Write("wall.ply", wall);
  const RunResult w = Run("world --result=" + result + " --name=arm --scan=" + scan + " --out_dir=" + Path("world"));
  ASSERT_EQ(w.exit_code, 0) << w.err;
  Write("traj.csv", "joint_1,joint_2\n0.1,0.2\n-0.6,0.9\n");
  const std::string report = Path("clearance.html");
  const RunResult c = Run("clearance --world=" + Path("world") + " --trajectory=" + Path("traj.csv") +
                          " --out_report=" + report);
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(c.out.find("report: " + report), std::string::npos) << c.out;
  const std::string page = Slurp(report);
  const std::string open = "<script type=\"application/json\" id=\"data\">";
  const size_t from = page.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(page.substr(from, page.find("</script>", from) - from));
  EXPECT_EQ(data["machine"], "arm");
  ASSERT_EQ(data["notes"].size(), 2u);
  EXPECT_NE(data["notes"][0].get<std::string>().find("free"), std::string::npos);
  int background = 0, links = 0;
  for (const nlohmann::json& part : data["parts"]) {
    background += part["kind"] == "background";
    links += part["kind"] == "machine" && part["machine"] == "arm";
  }
  EXPECT_EQ(background, 1);
  EXPECT_EQ(links, 9);  // the bundled robot's links with meshes
  EXPECT_NE(page.find("the outer faces of its 20 mm voxels"), std::string::npos);
  ExpectBadInput("clearance --world=" + Path("world") + " --out_report=" + Path("absent/r.html"), "absent");

  if (!HaveBrowser()) GTEST_SKIP() << "chromium is not installed (./scripts/install-deps.sh installs it)";
  std::string dom;
  const std::string status = BrowserStatus(report, &dom);
  EXPECT_EQ(status.rfind("ok: ", 0), 0u) << status;
  EXPECT_NE(status.find(" pixels drawn, " + std::to_string(data["parts"].size()) + " parts"), std::string::npos)
      << status;
  EXPECT_GT(std::atoi(status.c_str() + 4), 5000) << status;
}

}  // namespace
