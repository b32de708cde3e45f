// edgefit scan --scene and edgefit cell through the command line: a small
// cell of two balancer arms and an arm that is not looked for, written as
// E57, both found and their points gone from the background; the search
// limited to a region of interest; bad scene and model files and regions
// end with exit 2, one line naming the file, and no output; an arm half
// hidden behind another found and fitted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace edgefit_cli_test {
namespace {

const std::string kModels = std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/";

class CellCliTest : public CliTest {
 protected:
  std::string Scene() {
    return Write("scene.json",
                 "{\"assets\": [\n"
                 " {\"name\": \"a\", \"urdf\": \"" +
                     kModels +
                     "balancer_arm.urdf\", "
                     "\"joints\": \"joint_1=20deg,joint_2=-0.3\", \"base\": [-1.0, 0, 0]},\n"
                     " {\"name\": \"b\", \"urdf\": \"" +
                     kModels +
                     "balancer_arm.urdf\", "
                     "\"joints\": \"joint_1=-30deg,joint_2=0.2\", \"base\": [1.0, 0.3, 90]},\n"
                     " {\"name\": \"other\", \"urdf\": \"" +
                     kModels + "fk_arm.urdf\", \"base\": [0, 2.0, 0]}]}\n");
  }
  std::string Models(const std::string& count) {
    return Write("models.json", "{\"models\": [{\"name\": \"arm\", \"urdf\": \"" + kModels +
                                    "balancer_arm.urdf\", \"count\": " + count + "}]}\n");
  }
};
// Whole cell fits: the e2e label (cli_fixture.h, CliE2eTest).
class CellCliE2eTest : public CellCliTest {};

TEST_F(CellCliE2eTest, FindsBothArmsAndWritesTheBackground) {
  const RunResult scan = Run("scan --scene=" + Scene() +
                             " --scanners=3 --spacing_mm=6 --seed=3 --out=" + Path("cell.e57") +
                             " --truth=" + Path("truth.json") + " --labels=" + Path("labels.bin"));
  ASSERT_EQ(scan.exit_code, 0) << scan.err;
  const nlohmann::json truth = nlohmann::json::parse(Slurp(Path("truth.json")));
  ASSERT_EQ(truth["assets"].size(), 3u);
  EXPECT_EQ(truth["assets"][1]["name"], "b");
  EXPECT_GT(truth["assets"][1]["counts"]["link"].get<size_t>(), 1000u);

  const RunResult cell =
      Run("cell --models=" + Models("\"every\"") + " --scan=" + Path("cell.e57") +
          " --truth=" + Path("truth.json") + " --out=" + Path("r.json") +
          " --out_dir=" + Path("instances/new") + " --out_background=" + Path("rest.e57"));
  ASSERT_EQ(cell.exit_code, 0) << cell.err;
  const nlohmann::json r = nlohmann::json::parse(Slurp(Path("r.json")));
  ASSERT_EQ(r["instances"].size(), 2u);
  EXPECT_EQ(r["models"][0]["found"], 2);
  EXPECT_NE(r["models"][0]["stopped"].get<std::string>(), "");  // why no third
  EXPECT_TRUE(r["ok"].get<bool>());
  EXPECT_EQ(r["truth_assets_not_found"], nlohmann::json::array({"other"}));
  for (const auto& instance : r["instances"]) {
    EXPECT_LT(instance["base_error_mm"].get<double>(), 1.0) << instance["id"];
    // Written station poses are exact here: the survey's frame is the world.
    EXPECT_NEAR(instance["base_survey_error_mm"].get<double>(),
                instance["base_error_mm"].get<double>(), 1e-9)
        << instance["id"];
    // The arms' square bases: joint_1 nearest zero of the quarter turns,
    // which the truth's 20 and -30 deg are.
    EXPECT_LT(instance["worst_revolute_error_deg"].get<double>(), 0.05) << instance["id"];
    const nlohmann::json result =
        nlohmann::json::parse(Slurp(instance["result"].get<std::string>()));
    EXPECT_TRUE(result.contains("joint_status"));
    // Its errors as edgefit fit --truth writes them, with the truth asset.
    EXPECT_EQ(result["errors"]["truth_asset"], instance["truth_asset"]);
    EXPECT_NEAR(result["errors"]["base_translation_m"].get<double>() * 1e3,
                instance["base_error_mm"].get<double>(), 1e-9);
    EXPECT_LT(result["errors"]["tool_tip_m"].get<double>(), 0.002) << instance["id"];
  }
  const RunResult rest = Run("info --json --scan=" + Path("rest.e57"));
  ASSERT_EQ(rest.exit_code, 0) << rest.err;
  EXPECT_EQ(nlohmann::json::parse(rest.out)["total_valid"].get<size_t>(),
            r["background"]["points"].get<size_t>());
  EXPECT_GT(r["background"]["removed_points"].get<size_t>(), 20000u);
  // The instances' results (their inputs name the model) make a world.
  const RunResult world =
      Run("world --result=" + r["instances"][0]["result"].get<std::string>() + "," +
          r["instances"][1]["result"].get<std::string>() + " --out_dir=" + Path("world") +
          " --labels=" + Path("labels.bin"));
  ASSERT_EQ(world.exit_code, 0) << world.err;
  // Two of one robot: named by their results (the instances' ids).
  const std::string id = r["instances"][1]["id"].get<std::string>();
  EXPECT_NE(Slurp(Path("world/cell.urdf")).find("<joint name=\"world_to_" + id + "\""),
            std::string::npos);
  // The cell's scans less the same points as edgefit cell took: its
  // background, less the mixed pixels and what floats beside the arms.
  const size_t line = world.out.find("background: ");
  ASSERT_NE(line, std::string::npos) << world.out;
  unsigned long kept = 0, taken = 0, mixed = 0, floating = 0;
  ASSERT_EQ(std::sscanf(world.out.c_str() + line,
                        "background: %lu points (%lu of the machines removed, %lu mixed pixels and %lu",
                        &kept, &taken, &mixed, &floating),
            4)
      << world.out;
  EXPECT_EQ(kept + mixed + floating, r["background"]["points"].get<size_t>());
  EXPECT_LT(mixed + floating, r["background"]["points"].get<size_t>() / 100);
  EXPECT_TRUE(fs::exists(Path("world/background.bt")));
  EXPECT_TRUE(fs::exists(Path("world/background.ply")));
  // Against the labels: the true background kept, none of it taken by the
  // arms (world_truth.h; "other", not found, stays background).
  const size_t truth_line = world.out.find("truth (");
  ASSERT_NE(truth_line, std::string::npos) << world.out;
  double covered = 0, ghosts = 0, machine = 0, accessory = 0, far_taken = 0;
  ASSERT_EQ(std::sscanf(world.out.c_str() + truth_line,
                        "truth (--labels, mixed pixels left out): background points within 30 mm of "
                        "background.ply %lf %%; machine and accessory points inside it or within 10 mm "
                        "%lf %%; machine points within 10 mm of machines_as_scanned.ply %lf %%, "
                        "accessory points within 30 mm %lf %%; background points farther than 100 mm "
                        "from the machines' within 10 mm of it %lf %%",
                        &covered, &ghosts, &machine, &accessory, &far_taken),
            5)
      << world.out;
  EXPECT_GT(covered, 99.0) << world.out;
  EXPECT_GT(machine, 50.0) << world.out;
  EXPECT_LT(far_taken, 0.1) << world.out;
  // Each arm as scanned is clear of everything: no ghost of its own points
  // is left in its way.
  for (const nlohmann::json& instance : r["instances"]) {
    const RunResult c = Run("clearance --world=" + Path("world") + " --machine=" +
                            instance["id"].get<std::string>() + " --json");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const nlohmann::json as_scanned = nlohmann::json::parse(c.out)["waypoints"][0];
    EXPECT_FALSE(as_scanned["colliding"].get<bool>()) << c.out;
    EXPECT_GT(as_scanned["distance_to_background"].get<double>(), 0.0) << c.out;
  }
}

// --roi: the arms are looked for in the box around "a" only; "b" stays in
// the background, and a's points leave the whole scan.
TEST_F(CellCliE2eTest, TheRegionOfInterestLimitsTheSearch) {
  const RunResult scan = Run("scan --scene=" + Scene() +
                             " --scanners=3 --spacing_mm=6 --seed=3 --out=" + Path("cell.e57") +
                             " --truth=" + Path("truth.json"));
  ASSERT_EQ(scan.exit_code, 0) << scan.err;
  const std::string cell = "cell --models=" + Models("\"every\"") + " --scan=" + Path("cell.e57") +
                           " --truth=" + Path("truth.json") + " --out=" + Path("r.json");
  const RunResult run = Run(cell + " --roi=-2.2,-1.2,-0.5,-0.1,1.2,3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json r = nlohmann::json::parse(Slurp(Path("r.json")));
  ASSERT_EQ(r["instances"].size(), 1u);
  EXPECT_EQ(r["instances"][0]["truth_asset"], "a");
  EXPECT_LT(r["instances"][0]["worst_revolute_error_deg"].get<double>(), 0.05);
  EXPECT_EQ(r["truth_assets_not_found"], nlohmann::json::array({"b", "other"}));
  EXPECT_GT(r["roi"]["points"].get<size_t>(), 10000u);
  EXPECT_GT(r["background"]["removed_points"].get<size_t>(), 10000u);
  EXPECT_EQ(r["roi"]["min"], nlohmann::json::array({-2.2, -1.2, -0.5}));

  // edgefit fit on the same box, scored against the cell's truth: the asset
  // of this model whose base is nearest the fitted one.
  const std::string arm = " --urdf=" + kModels + "balancer_arm.urdf --scan=" + Path("cell.e57");
  const RunResult fit = Run("fit" + arm + " --roi=-2.2,-1.2,-0.5,-0.1,1.2,3 --truth=" +
                            Path("truth.json") + " --out=" + Path("f.json"));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const nlohmann::json f = nlohmann::json::parse(Slurp(Path("f.json")));
  EXPECT_EQ(f["errors"]["truth_asset"], "a");
  EXPECT_LT(f["errors"]["base_translation_m"].get<double>(), 1e-3);
  EXPECT_LT(std::abs(f["errors"]["joints"]["joint_2"].get<double>()), 0.05 * M_PI / 180.0);

  // A box without points and a malformed box: exit 2, one line, no output.
  fs::remove(Path("r.json"));
  for (const std::string roi : {"10,10,10,11,11,11", "1,2,3"}) {
    const RunResult bad = Run(cell + " --roi=" + roi);
    EXPECT_EQ(bad.exit_code, 2) << roi << "\n" << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find(roi == "1,2,3" ? "--roi" : "region of interest"), std::string::npos)
        << bad.err;
    EXPECT_FALSE(fs::exists(Path("r.json")));
  }
}

// An instance half hidden by another: two stations on one side, arm "b"
// standing behind arm "a" keeps 44 % of the points a scan of it alone has
// (56 % of its base's cells, 38 % of its column's). Both are found, none
// is invented, and the hidden one is fitted.
TEST_F(CellCliE2eTest, FindsAnArmHalfHiddenBehindAnother) {
  const std::string arm = "{\"urdf\": \"" + kModels + "balancer_arm.urdf\", ";
  const std::string a = arm + "\"name\": \"a\", \"joints\": \"joint_1=20deg,joint_2=-0.3\", " +
                        "\"base\": [0, 0, 0]}";
  const std::string b = arm + "\"name\": \"b\", \"joints\": \"joint_1=-30deg,joint_2=0.2\", " +
                        "\"base\": [0.1, 1.0, 90]}";
  const std::string stations = " --scanner_at=-0.5,-4.0,1.5:0.7,-4.2,1.6 --spacing_mm=6 --seed=3";
  const std::string both = Write("both.json", "{\"assets\": [" + a + ", " + b + "]}");
  const std::string alone = Write("alone.json", "{\"assets\": [" + b + "]}");
  ASSERT_EQ(Run("scan --scene=" + both + stations + " --out=" + Path("cell.e57") +
                " --truth=" + Path("truth.json"))
                .exit_code,
            0);
  ASSERT_EQ(Run("scan --scene=" + alone + stations + " --out=" + Path("alone.e57") +
                " --truth=" + Path("alone_truth.json"))
                .exit_code,
            0);
  const size_t hidden_points =
      nlohmann::json::parse(Slurp(Path("truth.json")))["assets"][1]["counts"]["link"];
  const size_t alone_points =
      nlohmann::json::parse(Slurp(Path("alone_truth.json")))["assets"][0]["counts"]["link"];
  EXPECT_LT(static_cast<double>(hidden_points), 0.5 * static_cast<double>(alone_points));

  const RunResult cell =
      Run("cell --models=" + Models("\"every\"") + " --scan=" + Path("cell.e57") +
          " --truth=" + Path("truth.json") + " --out=" + Path("r.json"));
  ASSERT_EQ(cell.exit_code, 0) << cell.err;
  const nlohmann::json r = nlohmann::json::parse(Slurp(Path("r.json")));
  ASSERT_EQ(r["instances"].size(), 2u);
  EXPECT_EQ(r["truth_assets_not_found"], nlohmann::json::array());
  for (const auto& instance : r["instances"]) {
    EXPECT_TRUE(instance["ok"].get<bool>()) << instance["id"] << ": " << instance["message"];
    EXPECT_LT(instance["base_error_mm"].get<double>(), 1.0) << instance["id"];
    EXPECT_LT(instance["worst_revolute_error_deg"].get<double>(), 0.2) << instance["id"];
  }
}

TEST_F(CellCliTest, BadSceneAndModelFilesExitTwoWithoutOutput) {
  const std::string scene_out = " --out=" + Path("c.e57") + " --truth=" + Path("t.json");
  struct Case {
    std::string args, file, expected;
  };
  const std::string no_base =
      Write("no_base.json", "{\"assets\": [{\"urdf\": \"" + kModels + "fk_arm.urdf\"}]}");
  const std::string empty = Write("empty.json", "{\"assets\": []}");
  const std::string not_json = Write("not_json.json", "assets: none");
  const std::string count_zero = Models("0");
  const std::string no_mesh = Write("no_mesh.json", "{\"models\": [{\"urdf\": \"nowhere.urdf\"}]}");
  const Case cases[] = {
      {"scan --scene=" + no_base + scene_out, no_base, "\"base\" must be [x, y, yaw_deg]"},
      {"scan --scene=" + empty + scene_out, empty, "no \"assets\" array"},
      {"scan --scene=" + not_json + scene_out, not_json, "not a JSON object"},
      {"scan --scene=" + no_base + " --urdf=" + kModels + "fk_arm.urdf" + scene_out, "--scene",
       "drop --urdf"},
      {"cell --models=" + count_zero + " --scan=x.e57 --out=" + Path("r.json"), count_zero,
       "\"count\" must be"},
      {"cell --models=" + no_mesh + " --scan=x.e57 --out=" + Path("r.json"), "nowhere.urdf",
       "nowhere.urdf"},
      // Output paths are checked before the scans are read, not after the fit.
      {"cell --models=" + count_zero + " --scan=x.e57 --out=" + Path("no_such_folder/r.json"),
       "no_such_folder", "does not exist"},
      {"cell --models=" + count_zero + " --scan=x.e57 --out=" + Path("r.json") +
           " --out_dir=" + not_json,
       not_json, "is not a folder"},
  };
  for (const Case& c : cases) {
    const RunResult r = Run(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    for (const char* output : {"c.e57", "t.json", "r.json"})
      EXPECT_FALSE(fs::exists(Path(output))) << output;
  }
}

}  // namespace
}  // namespace edgefit_cli_test
