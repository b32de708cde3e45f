// edgefit fit --out_report and edgefit report, tested as a person would use
// them: the report opens offline in headless Chromium (Debian's chromium,
// software WebGL) without a script error, draws the scan and the model, and
// shows the joint table and the edge map (that part skipped when chromium is not installed).
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
using edgefit_cli_test::kBalancerArm;
namespace fs = std::filesystem;

// The fit's report, and edgefit report from its result.json: a whole fit and
// a headless browser, the release half only (123 s under the sanitizers).
using ReportCliE2eTest = CliTest;
TEST_F(ReportCliE2eTest, FitReportOpensOfflineAndShowsScanModelAndJoints) {
  const std::string scan = Path("arm.ptx"), truth = Path("truth.json");
  ASSERT_EQ(Run("scan --urdf=" + kBalancerArm + " --scanners=2 --accessories --out=" + scan +
                " --truth=" + truth)
                .exit_code,
            0);
  // The report in a folder of its own: it needs no file beside it.
  fs::create_directories(Path("report"));
  const std::string report = Path("report/arm report.html");
  const RunResult r = Run("fit --urdf=" + kBalancerArm + " --scan=" + scan + " --truth=" + truth +
                          " --out=" + Path("result.json") + " --out_report='" + report + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = Slurp(report);
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.find("src=\""), std::string::npos) << "the page loads no file";
  EXPECT_EQ(html.find("href=\""), std::string::npos) << "the page links no file";
  // What each station saw, as PNG files beside the report.
  for (const char* png : {"report/arm report_station_1.png", "report/arm report_station_2.png"}) {
    EXPECT_EQ(Slurp(Path(png)).substr(0, 8), "\x89PNG\r\n\x1a\n") << png;
  }
  EXPECT_FALSE(fs::exists(Path("report/arm report_station_3.png")));

  // edgefit report makes the same report from result.json, whose inputs
  // (absolute paths) name the model and scans: from any folder.
  const nlohmann::json result = nlohmann::json::parse(Slurp(Path("result.json")));
  EXPECT_EQ(result["inputs"]["urdf"], kBalancerArm);
  EXPECT_EQ(result["inputs"]["scan"][0], scan);
  const RunResult again = Run("report --result=" + Path("result.json") + " --out=" + Path("r.html"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const std::string from_result = Slurp(Path("r.html"));
  EXPECT_NE(from_result.find("\"joint_2\""), std::string::npos);
  EXPECT_NE(from_result.find("THREE.OrbitControls"), std::string::npos);
  // Not a fit's result: bad input, nothing written.
  ExpectBadInput("report --result=" + Path("result.json") + "x --out=" + Path("x.html"),
                 "result.jsonx");
  Write("other.json", "{\"joints\": {}}");
  ExpectBadInput("report --result=" + Path("other.json") + " --out=" + Path("x.html"),
                 "other.json: not a result.json of edgefit fit");
  EXPECT_FALSE(fs::exists(Path("x.html")));

  if (!HaveBrowser()) {
    GTEST_SKIP() << "chromium is not installed (./scripts/install-deps.sh installs it)";
  }
  std::string page;
  const std::string status = BrowserStatus(report, &page);
  const std::string ok = "ok: ", drawn = " pixels drawn";
  ASSERT_EQ(status.compare(0, ok.size(), ok), 0) << status;
  ASSERT_GT(status.size(), ok.size() + drawn.size()) << status;
  ASSERT_EQ(status.substr(status.size() - drawn.size()), drawn) << status;
  const std::string pixels = status.substr(ok.size(), status.size() - ok.size() - drawn.size());
  ASSERT_EQ(pixels.find_first_not_of("0123456789"), std::string::npos) << status;
  EXPECT_GT(std::stol(pixels), 20000) << "the 3D view is nearly blank";
  // The tables the script built from the result.
  for (const char* text : {"joint_1", "joint_2", "piston_joint", "fit ok", "link_2",
                           "src=\"data:image/png;base64,", "station 2",
                           "valid edge regions (", "edge map (Sec. 4, Eq. 6)"}) {
    EXPECT_NE(page.find(text), std::string::npos) << text;
  }
}

TEST_F(CliTest, FitReportToAMissingFolderIsBadInputBeforeTheFit) {
  const std::string report = Path("no_such_folder/r.html");
  ExpectBadInput("fit --urdf=" + kBalancerArm + " --scan=" + std::string(EDGEFIT_SOURCE_DIR) +
                     "/assets/samples/two_scans.ptx --out=" + Path("r.json") +
                     " --out_report=" + report,
                 "no_such_folder");
  EXPECT_FALSE(fs::exists(Path("r.json")));
}

}  // namespace
