// edgefit fit through the command line: the result.json contract of
// DESIGN.md, the optional outputs, truth comparison, bad input.
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliE2eTest;
using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
using edgefit_cli_test::kBalancerArm;
namespace fs = std::filesystem;

TEST_F(CliTest, FitWritesTheResultContract) {
  const std::string scan = Path("arm.ptx"), truth = Path("truth.json");
  ASSERT_EQ(Run("scan --urdf=" + kBalancerArm + " --accessories --scanners=2 --out=" + scan +
                " --truth=" + truth)
                .exit_code,
            0);
  const RunResult r =
      Run("fit --urdf=" + kBalancerArm + " --scan=" + scan + " --truth=" + truth +
          " --out=" + Path("result.json") + " --out_joint_states=" + Path("j.yaml") +
          " --out_urdf=" + Path("fitted.urdf") + " --out_ply=" + Path("model.ply") +
          " --out_background=" + Path("background.ptx") + " --refine_chain" +
          " --norefine_without_mixed_pixels --mixed_pixel_neighbour_lines=0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json result = nlohmann::json::parse(Slurp(Path("result.json")));
  EXPECT_EQ(result["kind"], "articulated");
  EXPECT_EQ(result["base"]["xyz"].size(), 3u);
  EXPECT_EQ(result["base"]["rpy"].size(), 3u);
  EXPECT_EQ(result["base"]["T_world_base"].size(), 4u);
  // Every non-fixed joint, dependent ones included.
  for (const char* joint : {"joint_1", "joint_2", "cylinder_joint", "piston_joint", "rod_joint"}) {
    EXPECT_TRUE(result["joints"].contains(joint)) << joint;
    EXPECT_TRUE(result["joint_types"].contains(joint)) << joint;
  }
  EXPECT_EQ(result["joint_types"]["joint_1"], "revolute");
  EXPECT_EQ(result["joint_types"]["piston_joint"], "prismatic");
  for (const char* stage : {"load", "edges", "base_rough", "base_precise", "chain", "refine",
                            "alternatives", "mixed_pixels", "total"}) {
    EXPECT_TRUE(result["timing_s"].contains(stage)) << stage;
  }
  // The refinement's mask of the mixed pixels (on by default) was found.
  EXPECT_GT(result["timing_s"]["mixed_pixels"].get<double>(), 0.0);
  // The alternatives' checks are a part of the stages they run in.
  EXPECT_LE(result["timing_s"]["alternatives"].get<double>(),
            result["timing_s"]["base_precise"].get<double>() +
                result["timing_s"]["chain"].get<double>() +
                result["timing_s"]["refine"].get<double>());
  EXPECT_TRUE(result["quality"]["ok"].get<bool>()) << result["quality"].dump();
  EXPECT_EQ(result["mixed_pixels_removed"].get<size_t>(), 0u);  // not asked for
  // A laser scan: up is its z, its noise (1 mm) leaves every threshold as it is.
  EXPECT_EQ(result["up"]["from"], "frame");
  EXPECT_EQ(result["up"]["vector"][2].get<double>(), 1.0);
  EXPECT_GT(result["noise"]["sigma_m"].get<double>(), 0.0);
  EXPECT_EQ(result["noise"]["scale"].get<double>(), 1.0);
  // The options as given, defaults included.
  const nlohmann::json& options = result["options"];
  EXPECT_EQ(options["weighting"], "uniform");
  EXPECT_DOUBLE_EQ(options["visibility_tolerance_m"].get<double>(), 0.002);
  EXPECT_DOUBLE_EQ(options["incidence_cosine"].get<double>(), 0.0);  // off
  EXPECT_TRUE(options["align_stations"].get<bool>());
  EXPECT_EQ(options["covering_rounds"].get<int>(), 2);
  EXPECT_DOUBLE_EQ(options["pair_sweep_step_rad"].get<double>(), 5.0 * M_PI / 180.0);
  EXPECT_FALSE(options["remove_mixed_pixels"].get<bool>());
  EXPECT_FALSE(options["refine_without_mixed_pixels"].get<bool>());
  EXPECT_EQ(options["mixed_pixels"]["neighbour_lines"].get<int>(), 0);
  EXPECT_EQ(options["mixed_pixels"]["min_lines"].get<int>(), 3);
  EXPECT_TRUE(result["quality"]["per_link"].contains("link_2"));
  // The arm scanned at its zero posture: joints within 0.1 degrees.
  EXPECT_LT(result["errors"]["joints"]["joint_1"].get<double>(), 0.1 * M_PI / 180.0);
  EXPECT_LT(result["errors"]["joints"]["joint_2"].get<double>(), 0.1 * M_PI / 180.0);
  EXPECT_LT(result["errors"]["base_translation_m"].get<double>(), 0.001);
  EXPECT_LT(result["errors"]["tool_tip_m"].get<double>(), 0.002);
  // --refine_chain ran; the covariance gives every independent joint a
  // standard deviation (dependent ones follow theirs and have none).
  const nlohmann::json& chain = result["quality"]["chain_refinement"];
  EXPECT_TRUE(chain["refined"].get<bool>());
  EXPECT_GE(chain["iterations"].get<int>(), 1);
  EXPECT_TRUE(chain["covariance_ok"].get<bool>()) << chain.dump();
  for (const char* joint : {"joint_1", "joint_2"}) {
    ASSERT_TRUE(result["joint_std"][joint].is_number()) << result["joint_std"].dump();
    EXPECT_GT(result["joint_std"][joint].get<double>(), 0.0);
    EXPECT_LT(result["joint_std"][joint].get<double>(), 0.1 * M_PI / 180.0);
  }
  EXPECT_FALSE(result["joint_std"].contains("cylinder_joint"));
  EXPECT_EQ(result["base_std"]["xyz_m"].size(), 3u);
  // A verdict for every independent joint, in result.json and as comments
  // in the joint states and the calibrated URDF.
  for (const char* joint : {"joint_1", "joint_2"}) {
    EXPECT_EQ(result["joint_status"][joint]["verdict"], "ok") << result["joint_status"].dump();
    EXPECT_EQ(result["joint_status"][joint]["std"], result["joint_std"][joint]);
  }
  // The arm's square base looks the same every quarter turn: joint_1's
  // other placements are listed with the base's turn, joint_2 has none.
  const auto& alternatives = result["joint_status"]["joint_1"]["alternatives"];
  ASSERT_EQ(alternatives.size(), 3u) << alternatives.dump();
  EXPECT_EQ(alternatives[0]["base_turn_deg"], -90);
  EXPECT_TRUE(result["joint_status"]["joint_1"].contains("convention"));
  EXPECT_TRUE(result["joint_status"]["joint_2"]["alternatives"].empty());
  EXPECT_FALSE(result["joint_status"].contains("cylinder_joint"));
  const std::string yaml = Slurp(Path("j.yaml"));
  EXPECT_NE(yaml.find("name: [joint_1, joint_2"), std::string::npos);
  EXPECT_NE(yaml.find("# verdicts: joint_1=ok joint_2=ok"), std::string::npos) << yaml;
  const std::string urdf = Slurp(Path("fitted.urdf"));
  EXPECT_NE(urdf.find(" [ok]"), std::string::npos);
  EXPECT_NE(urdf.find("<link name=\"world\"/>"), std::string::npos);
  EXPECT_NE(urdf.find("world_to_base_link"), std::string::npos);
  const std::string ply = Slurp(Path("model.ply"));
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_NE(ply.find("element face"), std::string::npos);
  // The background keeps the scan's layout, without the arm's points.
  const size_t removed = result["background"]["removed_points"].get<size_t>();
  EXPECT_GT(removed, 1000u);
  const RunResult info = Run("info --json --scan=" + Path("background.ptx"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const RunResult original = Run("info --json --scan=" + scan);
  const nlohmann::json kept = nlohmann::json::parse(info.out);
  const nlohmann::json all = nlohmann::json::parse(original.out);
  size_t valid = 0, original_valid = 0;
  for (const auto& s : kept["scans"]) valid += s["valid"].get<size_t>();
  for (const auto& s : all["scans"]) original_valid += s["valid"].get<size_t>();
  EXPECT_EQ(valid + removed, original_valid);
}

// The release half (e2e); under the sanitizers the conveyance fit runs in
// SmallSceneFitTest.ConveyorFromItsArmTips.
TEST_F(CliE2eTest, FitTellsAConveyorFromItsModel) {
  // --kind=auto: a model with prismatic joints only is a conveyance system;
  // its base's rough pose comes from the arm tips (paper Sec. 6.1).
  const std::string conveyor = std::string(EDGEFIT_SOURCE_DIR) + "/assets/conveyor/conveyor.urdf";
  const std::string scan = Path("conveyor.ptx"), truth = Path("truth.json");
  ASSERT_EQ(Run("scan --urdf=" + conveyor +
                " --random_pose --seed=3 --base=0.3,0.2,-70 "
                "--spacing_mm=6 --out=" +
                scan + " --truth=" + truth)
                .exit_code,
            0);
  const RunResult r = Run("fit --urdf=" + conveyor + " --scan=" + scan + " --truth=" + truth +
                          " --out=" + Path("result.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json result = nlohmann::json::parse(Slurp(Path("result.json")));
  EXPECT_EQ(result["kind"], "conveyance");
  EXPECT_EQ(result["quality"]["base_rough"]["method"], "arm_tips");
  EXPECT_TRUE(result["quality"]["ok"].get<bool>()) << result["quality"].dump();
  EXPECT_LT(result["errors"]["base_translation_m"].get<double>(), 0.001);
  for (const auto& [joint, error] : result["errors"]["joints"].items()) {
    EXPECT_LT(error.get<double>(), 0.001) << joint;
  }
}

TEST_F(CliTest, FitBadInput) {
  const std::string sample = std::string(EDGEFIT_SOURCE_DIR) + "/assets/samples/two_scans.ptx";
  const std::string conveyor = std::string(EDGEFIT_SOURCE_DIR) + "/assets/conveyor/conveyor.urdf";
  const std::string out = " --out=" + Path("result.json");
  ExpectBadInput("fit --scan=" + sample + out, "--urdf is required");
  ExpectBadInput("fit --urdf=" + kBalancerArm + out, "--scan is required");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample, "--out is required");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + Path("none.ptx") + out, "none.ptx");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --roi=1,2,3",
                 "--roi: expected");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --roi=50,50,0,51,51,1",
                 "--roi: the box holds none of the");
  ExpectBadInput("fit --urdf=" + Path("none.urdf") + " --scan=" + sample + out, "none.urdf");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --weighting=heavy",
                 "--weighting");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --init=1,2", "--init");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --loss=l3", "l3");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --up=0,0,0", "--up must");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --up=0,1", "--up must");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --mounting=roof",
                 "--mounting must");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --joints=nope=1",
                 "nope");
  ExpectBadInput("fit --urdf=" + conveyor + " --scan=" + sample + out + " --kind=crane",
                 "--kind must be auto, articulated or conveyance");
  ExpectBadInput(
      "fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --background_distance_mm=-1",
      "--background_distance_mm");
  // Output paths are checked before the scans are read, not after the fit.
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + Path("none.ptx") +
                     " --out=" + Path("no_such_folder/result.json"),
                 "the folder " + Path("no_such_folder") + " does not exist");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + sample + out + " --out_urdf=" + Path(""),
                 "is a folder, not a file name");
  EXPECT_FALSE(fs::exists(Path("result.json")));
}

}  // namespace
