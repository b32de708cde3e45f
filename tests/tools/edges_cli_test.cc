// edgefit edges through the command line: the weights file layout of
// DESIGN.md, the JSON summary, scoring against labels, bad input.
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
using edgefit_cli_test::kBalancerArm;
namespace fs = std::filesystem;

// A scan and edge detection of it: the release half only (71 s under the
// sanitizers, where edges_test covers the detector).
using EdgesCliE2eTest = CliTest;
TEST_F(EdgesCliE2eTest, EdgesWritesWeightsJsonAndPly) {
  const std::string scan = Path("arm.ptx"), labels = Path("arm.labels");
  const RunResult s = Run("scan --urdf=" + kBalancerArm + " --accessories --scanners=2 --out=" + scan +
                          " --truth=" + Path("arm.json") + " --labels=" + labels);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const RunResult r = Run("edges --scan=" + scan + " --labels=" + labels + " --out_weights=" +
                          Path("w.bin") + " --out_json=" + Path("e.json") + " --out_ply=" +
                          Path("e.ply") + " --w_high=7");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Progress only on a terminal, unless asked (stderr is a pipe here).
  EXPECT_EQ(r.err.find("edges: "), std::string::npos) << r.err;
  const RunResult logged =
      Run("edges --progress=always --scan=" + scan + " --out_weights=" + Path("w2.bin") +
          " --out_json=" + Path("e2.json"));
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  EXPECT_NE(logged.err.find("edges: "), std::string::npos) << logged.err;
  ExpectBadInput("edges --progress=sometimes --scan=" + scan, "--progress");
  const RunResult quiet = Run("edges --progress=always --quiet --scan=" + scan +
                              " --out_weights=" + Path("w3.bin") + " --out_json=" + Path("e3.json"));
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("edges: "), std::string::npos) << quiet.err;
  const nlohmann::json e = nlohmann::json::parse(Slurp(Path("e.json")));
  const nlohmann::json info = nlohmann::json::parse(Run("info --json --scan=" + scan).out);
  // One float32 per grid cell, scans in file order.
  const std::string w = Slurp(Path("w.bin"));
  ASSERT_EQ(w.size(), 4 * info["total_cells"].get<size_t>());
  std::vector<float> weights(w.size() / 4);
  std::memcpy(weights.data(), w.data(), w.size());
  size_t valid = 0, high = 0;
  for (float x : weights) {
    EXPECT_TRUE(x == 0.0f || x == 1.0f || x == 7.0f) << x;
    valid += x > 0.0f;
    high += x == 7.0f;
  }
  EXPECT_EQ(valid, info["total_valid"].get<size_t>());  // 0 exactly for missing cells
  EXPECT_EQ(valid, e["points"].get<size_t>());
  EXPECT_EQ(high, e["edge_points"].get<size_t>());
  EXPECT_GT(high, 0u);
  for (const char* stage : {"load", "normals", "scores", "region_growing", "edges", "total"}) {
    EXPECT_TRUE(e["timing_s"].contains(stage)) << stage;
  }
  ASSERT_TRUE(e.contains("metrics"));
  EXPECT_GT(e["metrics"]["true_edges"].get<size_t>(), 0u);
  EXPECT_GT(e["metrics"]["precision"].get<double>(), 0.0);
  EXPECT_GT(fs::file_size(Path("e.ply")), 1000u);
  // The ideal scanner makes no mixed pixels; the detector finds almost none.
  EXPECT_EQ(e["mixed_pixels"]["labelled"].get<size_t>(), 0u);
  EXPECT_LE(e["mixed_pixels"]["found"].get<size_t>(), valid / 1000);
  EXPECT_FALSE(e["mixed_pixels"]["removed"].get<bool>());
}

TEST_F(CliTest, EdgesBadInput) {
  const std::string sample = std::string(EDGEFIT_SOURCE_DIR) + "/assets/samples/two_scans.ptx";
  const std::string outs = " --out_weights=" + Path("w.bin") + " --out_json=" + Path("e.json");
  ExpectBadInput("edges" + outs, "--scan is required");
  ExpectBadInput("edges --scan=" + sample + " --out_json=" + Path("e.json"), "--out_weights");
  ExpectBadInput("edges --scan=" + sample + outs + " --r_min_mm=20", "r_min");
  ExpectBadInput("edges --scan=" + Path("none.ptx") + outs, "none.ptx");
  // Labels of another scan: the grids do not match.
  const std::string labels = Path("arm.labels");
  ASSERT_EQ(Run("scan --urdf=" + kBalancerArm + " --spacing_mm=8 --out=" + Path("arm.ptx") +
                " --truth=" + Path("arm.json") + " --labels=" + labels)
                .exit_code,
            0);
  ExpectBadInput("edges --scan=" + sample + " --labels=" + labels + outs, "do not match");
  EXPECT_FALSE(fs::exists(Path("w.bin")));
  EXPECT_FALSE(fs::exists(Path("e.json")));
}

}  // namespace
