// Runs the edgefit binary and checks the command-line contract (DESIGN.md):
// exit 0 on success, 2 on bad input with exactly one stderr line that names
// the file and the problem, nothing on stdout then, and no output files.
#ifndef EDGEFIT_TESTS_TOOLS_CLI_FIXTURE_H_
#define EDGEFIT_TESTS_TOOLS_CLI_FIXTURE_H_

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace edgefit_cli_test {

namespace fs = std::filesystem;

// The small articulated model most CLI tests scan and fit.
inline const std::string kBalancerArm =
    std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf";

struct RunResult {
  int exit_code = -1;
  bool signaled = false;
  std::string out;
  std::string err;
};

inline std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // A parameterized test's name holds a '/': one folder per test, not a
    // folder in a folder that TearDown would leave behind.
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    dir_ = fs::temp_directory_path() / ("edgefit_cli_" + std::to_string(::getpid()) + "_" + name);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, const std::string& content) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  RunResult Run(const std::string& args) {
    const std::string out = (dir_ / "stdout.txt").string();
    const std::string err = (dir_ / "stderr.txt").string();
    const std::string cmd = std::string(EDGEFIT_BINARY) + " " + args + " >" + out + " 2>" + err;
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.signaled = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = Slurp(out);
    r.err = Slurp(err);
    return r;
  }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  // Bad input: exit 2, nothing on stdout, one stderr line containing `needle`.
  void ExpectBadInput(const std::string& args, const std::string& needle) {
    const RunResult r = Run(args);
    EXPECT_FALSE(r.signaled) << args;
    EXPECT_EQ(r.exit_code, 2) << args << "\nstderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\nstderr: " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos)
        << args << "\nexpected '" << needle << "' in: " << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\nstdout: " << r.out;
  }

 public:
  // Whether Debian's chromium is installed (the report tests open pages in it).
  static bool HaveBrowser() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

  // Opens the page `html` offline in headless Chromium (software WebGL), from
  // its own folder, and returns the text of its element #status after the
  // page's scripts ran ("" when the page has none); *dom gets the page.
  std::string BrowserStatus(const std::string& html, std::string* dom) {
    const std::string dump = Path("dom.html");
    const std::string browse =
        "cd '" + fs::path(html).parent_path().string() +
        "' && timeout 120 chromium --headless --no-sandbox --use-angle=swiftshader "
        "--enable-unsafe-swiftshader --window-size=1280,800 --user-data-dir='" +
        Path("profile") + "' --dump-dom 'file://" + html + "' >" + dump + " 2>" +
        Path("chromium.log");
    EXPECT_EQ(std::system(browse.c_str()), 0) << Slurp(Path("chromium.log"));
    *dom = Slurp(dump);
    const std::string open = "<div id=\"status\">";
    const size_t at = dom->find(open);
    if (at == std::string::npos) return "";
    const size_t from = at + open.size();
    return dom->substr(from, dom->find("</div>", from) - from);
  }

 protected:
  fs::path dir_;
};

// The CLI tests that run whole fits of full scenes: the ctest label e2e
// (tests/CMakeLists.txt gives it to every suite named *E2eTest), so the
// release half of CI runs them and the sanitizer half does not.
class CliE2eTest : public CliTest {};

}  // namespace edgefit_cli_test

#endif  // EDGEFIT_TESTS_TOOLS_CLI_FIXTURE_H_
