// edgefit bench through the command line: the paper's tables for a small
// selection (one conveyor posture, coarse scan), CSV and JSON outputs, an
// ablation axis and its summary, the two-station base, bad flags.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliE2eTest;
using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
namespace fs = std::filesystem;

const std::string kAssets = std::string(EDGEFIT_SOURCE_DIR) + "/assets/";

// The bench's report of the refine_chains ablation (conveyor, one posture):
// its tables as on stdout, a plot of the error against the axis, and, in
// headless Chromium, no script error.
void ExpectBenchReport(CliTest* test, const std::string& html, const std::string& markdown) {
  const std::string page = Slurp(html);
  for (const char* text : {"Table 2: translation error per joint [mm]", "carriage_1_joint",
                           "Per setting (postures and repeats pooled)", "<svg",
                           "prismatic joints: mean error against whole-chain refinement",
                           "<td>refine_chain</td>", "<td>sequential</td>", "<text"}) {
    EXPECT_NE(page.find(text), std::string::npos) << text;
  }
  EXPECT_NE(markdown.find("| conveyor | without | edge | refine_chain | 1 |"), std::string::npos);
  EXPECT_EQ(page.find("src=\""), std::string::npos) << "the page loads no file";
  if (!CliTest::HaveBrowser()) return;
  std::string dom;
  EXPECT_EQ(test->BrowserStatus(html, &dom), "ok: 3 tables, 1 charts") << html;
}

// A conveyor fit through the bench: the release half (e2e); under the
// sanitizers the fit runs in SmallSceneFitTest and the tables' code in
// BenchReportFromSavedRuns.
TEST_F(CliE2eTest, BenchPrintsThePapersTables) {
  const RunResult r = Run("bench --assets=conveyor --conveyor_urdf=" + kAssets +
                          "conveyor/conveyor.urdf --conveyor_postures=" + kAssets +
                          "conveyor/postures.json --only=load --scenes=without "
                          "--weightings=edge --spacing_mm=8 --out_csv=" +
                          Path("bench.csv") + " --out_json=" + Path("bench.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## Table 2: translation error per joint [mm]"), std::string::npos);
  EXPECT_NE(r.out.find("| load | without | edge |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("carriage_1_joint"), std::string::npos) << r.out;
  const std::string csv = Slurp(Path("bench.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7) << csv;  // header + 6 joints
  const nlohmann::json json = nlohmann::json::parse(Slurp(Path("bench.json")));
  ASSERT_EQ(json.size(), 1u);
  EXPECT_EQ(json[0]["posture"], "load");
  EXPECT_FALSE(json[0]["failed"].get<bool>()) << json.dump();
  for (const auto& [joint, error] : json[0]["joint_errors"].items()) {
    EXPECT_LT(error.get<double>(), 0.002) << joint;  // 8 mm spacing: within 2 mm
  }
}

// The bench's tables and report from saved runs (8 fits of the conveyor kept
// in benchmarks/results), in both halves.
TEST_F(CliTest, BenchReportFromSavedRuns) {
  const std::string runs = std::string(EDGEFIT_SOURCE_DIR) +
                           "/benchmarks/results/2026-11-27-unmixed-refinement-conveyor-after.json";
  const RunResult r = Run("report --bench=" + runs + " --out=" + Path("bench.html"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## Table 2: translation error per joint [mm]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| load | with | uniform | 0.0630 |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| conveyor | random_4 | with | uniform |"), std::string::npos) << r.out;
  const std::string page = Slurp(Path("bench.html"));
  EXPECT_NE(page.find("Table 2: translation error per joint [mm]"), std::string::npos);
  EXPECT_NE(page.find("carriage_1_joint"), std::string::npos);
  EXPECT_EQ(page.find("src=\""), std::string::npos) << "the page loads no file";
}

TEST_F(CliE2eTest, BenchRunsTheProductOfItsAblationAxes) {
  const RunResult r =
      Run("bench --assets=conveyor --conveyor_urdf=" + kAssets +
          "conveyor/conveyor.urdf --conveyor_postures=" + kAssets +
          "conveyor/postures.json --only=load --scenes=without "
          "--weightings=edge --spacing_mm=8 --refine_chains=off,on --incidence_cosine=0.5 "
          "--out_json=" +
          Path("ablation.json") + " --out_report=" + Path("ablation.html"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("## Per setting"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| conveyor | without | edge | sequential | 1 |"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| conveyor | without | edge | refine_chain | 1 |"), std::string::npos)
      << r.out;
  const nlohmann::json json = nlohmann::json::parse(Slurp(Path("ablation.json")));
  ASSERT_EQ(json.size(), 2u);
  EXPECT_FALSE(json[0]["settings"]["refine_chain"].get<bool>());
  EXPECT_TRUE(json[1]["settings"]["refine_chain"].get<bool>());
  // Every run records the fit options it was made with, the fit flags given
  // to the bench among them.
  EXPECT_FALSE(json[0]["options"]["refine_chain"].get<bool>());
  EXPECT_TRUE(json[1]["options"]["refine_chain"].get<bool>());
  EXPECT_DOUBLE_EQ(json[1]["options"]["incidence_cosine"].get<double>(), 0.5);
  EXPECT_EQ(json[1]["options"]["weighting"], "edge");
  EXPECT_EQ(json[1]["label"], "refine_chain");
  EXPECT_EQ(json[1]["prismatic_joints"].size(), 6u);
  for (const auto& [joint, error] : json[1]["joint_errors"].items()) {
    EXPECT_LT(error.get<double>(), 0.002) << joint;
  }
  ExpectBenchReport(this, Path("ablation.html"), r.out);

  // edgefit report makes the same report again from the saved runs.
  const RunResult again =
      Run("report --bench=" + Path("ablation.json") + " --out=" + Path("again.html"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  ExpectBenchReport(this, Path("again.html"), r.out);
  Write("not_runs.json", "[{\"asset\": \"conveyor\"}]");
  ExpectBadInput("report --bench=" + Path("not_runs.json") + " --out=" + Path("x.html"),
                 "not_runs.json: run 1: posture missing");
  ExpectBadInput("report --bench=" + Path("ablation.json") + " --result=" + Path("r.json") +
                     " --out=" + Path("x.html"),
                 "give one of --result");
  EXPECT_FALSE(fs::exists(Path("x.html")));
}

// From two stations the bundled robot's square base looks the same turned
// a quarter turn: fitted from that rough pose alone, `home` came out 90
// degrees off and said ok. The near-equal rough pose fitted through the
// whole chain tells them apart.
TEST_F(CliE2eTest, BenchTwoStationsDoNotTurnTheBase) {
  const RunResult r = Run("bench --assets=robot --robot_urdf=" + kAssets +
                          "robot/robot.urdf --robot_attach=" + kAssets +
                          "robot/weld_gun.urdf@tool0 --robot_postures=" + kAssets +
                          "robot/postures.json --only=home --scenes=with --weightings=uniform "
                          "--spacing_mm=3 --scanners=2 --out_json=" +
                          Path("two_stations.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json json = nlohmann::json::parse(Slurp(Path("two_stations.json")));
  ASSERT_EQ(json.size(), 1u);
  EXPECT_TRUE(json[0]["ok"].get<bool>()) << json[0]["message"];
  EXPECT_LT(json[0]["base_rotation_rad"].get<double>(), 0.05 * M_PI / 180.0);
  EXPECT_GT(json[0]["timing_s"]["alternatives"].get<double>(), 0.0);
  // The base's error by world axis, to set against its std.
  double squares = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double component = json[0]["base_survey_rotation_world_rad"][i].get<double>();
    squares += component * component;
    EXPECT_GT(json[0]["base_std"]["rotation_rad"][i].get<double>(), 0.0) << i;
    EXPECT_GT(json[0]["base_std"]["xyz_m"][i].get<double>(), 0.0) << i;
  }
  EXPECT_NEAR(std::sqrt(squares), json[0]["base_survey_rotation_rad"].get<double>(), 1e-12);
}

TEST_F(CliTest, BenchBadInput) {
  ExpectBadInput("bench --lambdas=0.1,1", "pose_penalty");
  ExpectBadInput("bench --losses=l3", "l3");
  ExpectBadInput("bench --searches=octree", "--searches");
  ExpectBadInput("bench --refine_chains=maybe", "--refine_chains");
  ExpectBadInput("bench --noises_mm=loud", "loud");
  ExpectBadInput("bench --scanner_counts=1.5", "--scanner_counts");
  ExpectBadInput("bench --w_highs=0.5", "--w_highs");
  ExpectBadInput("bench --assets=crane", "--assets");
  ExpectBadInput("bench --scenes=maybe", "--scenes");
  ExpectBadInput("bench --weightings=heavy", "--weightings");
  ExpectBadInput("bench --assets=conveyor --conveyor_urdf=" + Path("none.urdf"), "none.urdf");
}

}  // namespace
