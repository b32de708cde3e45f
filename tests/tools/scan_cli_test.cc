// edgefit scan through the command line: outputs, determinism, read-back
// through edgefit info, and bad input without partial output.
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
using edgefit_cli_test::kBalancerArm;
namespace fs = std::filesystem;

class ScanCliTest : public CliTest {
 protected:
  // A small, fast scan of the balancer arm: coarse spacing, 2 scanners.
  std::string SmallScanArgs(const std::string& out, const std::string& truth) {
    return "scan --urdf=" + kBalancerArm + " --joints=joint_1=20deg,joint_2=-0.3 --seed=3 " +
           "--scanners=2 --spacing_mm=6 --out=" + out + " --truth=" + truth;
  }
};

TEST_F(ScanCliTest, WritesScanTruthAndLabelsThatReadBack) {
  const std::string out = Path("arm.ptx"), truth = Path("arm_truth.json"),
                    labels = Path("arm_labels.bin");
  const RunResult r = Run(SmallScanArgs(out, truth) + " --labels=" + labels);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(out));
  ASSERT_TRUE(fs::exists(labels));
  const nlohmann::json t = nlohmann::json::parse(Slurp(truth));
  EXPECT_NEAR(t["joints"]["joint_1"].get<double>(), 20.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(t["joints"]["joint_2"].get<double>(), -0.3, 1e-12);
  // Every non-fixed joint is in the truth, the loop-closure and mimic ones too.
  for (const char* joint : {"cylinder_joint", "piston_joint", "rod_joint"}) {
    EXPECT_TRUE(t["joints"].contains(joint)) << joint;
  }
  ASSERT_TRUE(t.contains("T_world_base"));
  ASSERT_EQ(t["scanners"].size(), 2u);

  // The scan reads back through edgefit info with two organized scans whose
  // estimated lattice steps agree with each other's spacing at the asset.
  const RunResult info = Run("info --json --scan=" + out);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const nlohmann::json j = nlohmann::json::parse(info.out);
  ASSERT_EQ(j["scans"].size(), 2u);
  for (const auto& s : j["scans"]) {
    EXPECT_GT(s["valid"].get<size_t>(), 500u);
    ASSERT_FALSE(s["lattice"].is_null());
    const double az = std::abs(s["lattice"]["azimuth_step_deg"].get<double>());
    const double el = std::abs(s["lattice"]["elevation_step_deg"].get<double>());
    EXPECT_NEAR(az, el, 0.01 * el);  // the scanner steps both angles alike
  }
}

TEST_F(ScanCliTest, SameSeedSameBytesAnyThreadCount) {
  const RunResult a = Run(SmallScanArgs(Path("a.ptx"), Path("a.json")) + " --threads=1");
  const RunResult b = Run(SmallScanArgs(Path("b.ptx"), Path("b.json")) + " --threads=2");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(Slurp(Path("a.ptx")), Slurp(Path("b.ptx")));
  const RunResult c = Run(SmallScanArgs(Path("c.ptx"), Path("c.json")) + " --seed=4");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(Slurp(Path("a.ptx")), Slurp(Path("c.ptx")));
}

// The same scan written as E57 and as PTX reads back the same (grids,
// valid points, poses, lattices), and a damaged E57 is refused with exit 2.
TEST_F(ScanCliTest, E57HoldsTheSameScansAsPtx) {
  ASSERT_EQ(Run(SmallScanArgs(Path("arm.e57"), Path("e.json"))).exit_code, 0);
  ASSERT_EQ(Run(SmallScanArgs(Path("arm.ptx"), Path("p.json"))).exit_code, 0);
  const RunResult e57 = Run("info --json --scan=" + Path("arm.e57"));
  const RunResult ptx = Run("info --json --scan=" + Path("arm.ptx"));
  ASSERT_EQ(e57.exit_code, 0) << e57.err;
  ASSERT_EQ(ptx.exit_code, 0) << ptx.err;
  nlohmann::json a = nlohmann::json::parse(e57.out), b = nlohmann::json::parse(ptx.out);
  ASSERT_EQ(a["scans"].size(), 2u);
  for (size_t s = 0; s < 2; ++s) {  // the pose through a quaternion: to 1e-12
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(a["scans"][s]["T_world_scanner"][r][c].get<double>(),
                    b["scans"][s]["T_world_scanner"][r][c].get<double>(), 1e-12);
      }
    }
  }
  for (nlohmann::json* j : {&a, &b}) {
    j->erase("files");
    for (auto& s : (*j)["scans"]) s.erase("source"), s.erase("T_world_scanner");
  }
  EXPECT_EQ(a, b);

  std::string bytes = Slurp(Path("arm.e57"));
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 1);
  {
    std::ofstream damaged(Path("damaged.e57"), std::ios::binary);
    damaged << bytes;
  }
  const RunResult bad = Run("fit --urdf=" + kBalancerArm + " --scan=" + Path("damaged.e57") + " --out=" + Path("r.json"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("damaged.e57: page "), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("fails its CRC-32C checksum"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(Path("r.json")));
}

TEST_F(ScanCliTest, ExplicitScannerPositions) {
  const std::string out = Path("s.ptx"), truth = Path("s.json");
  const RunResult r = Run("scan --urdf=" + kBalancerArm + " --spacing_mm=8 --out=" + out +
                          " --truth=" + truth + " --scanner_at=3,0.5,1.5:-2.5,-1,1.3,-20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json t = nlohmann::json::parse(Slurp(truth));
  ASSERT_EQ(t["scanners"].size(), 2u);
  const auto& T0 = t["scanners"][0];
  EXPECT_DOUBLE_EQ(T0[0][3].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(T0[1][3].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(T0[2][3].get<double>(), 1.5);
  // No yaw given: its +x looks back towards the arm near the origin.
  EXPECT_LT(T0[0][0].get<double>(), -0.9);
  const auto& T1 = t["scanners"][1];  // yaw -20 deg
  EXPECT_NEAR(T1[0][0].get<double>(), std::cos(-20.0 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(T1[1][0].get<double>(), std::sin(-20.0 * M_PI / 180.0), 1e-12);
  EXPECT_EQ(t["settings"]["scanners"].get<int>(), 2);
  ExpectBadInput("scan --urdf=" + kBalancerArm + " --out=" + Path("u.ptx") + " --truth=" +
                     Path("u.json") + " --scanner_at=1,2",
                 "--scanner_at");
  EXPECT_FALSE(fs::exists(Path("u.ptx")));
}

TEST_F(ScanCliTest, BadInputLeavesNoOutput) {
  const std::string out = Path("x.ptx"), truth = Path("x.json");
  ExpectBadInput("scan --out=" + out + " --truth=" + truth, "--urdf (or --scene) is required");
  ExpectBadInput("scan --urdf=" + kBalancerArm + " --out=" + Path("x.xyz") + " --truth=" + truth,
                 ".ptx, .e57 or .pcd");
  ExpectBadInput(SmallScanArgs(out, truth) + " --base=1,2", "--base");
  ExpectBadInput("scan --urdf=" + kBalancerArm + " --joints=joint_7=0.1 --out=" + out +
                     " --truth=" + truth,
                 "joint_7");
  ExpectBadInput("scan --urdf=" + kBalancerArm + " --joints=joint_2=90deg --out=" + out +
                     " --truth=" + truth,
                 "outside its limits");
  ExpectBadInput("scan --urdf=" + kBalancerArm + " --random_pose --joints=joint_1=0 --out=" + out +
                     " --truth=" + truth,
                 "at most one of");
  // The truth cannot be written: the scan that was already written is removed.
  ExpectBadInput(SmallScanArgs(out, "/nonexistent_edgefit_dir/t.json"), "t.json");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(truth));
}

}  // namespace
