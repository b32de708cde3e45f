// edgefit batch through the command line: jobs from a manifest, one fit
// process each; a failed job is reported and the batch goes on; shards split
// the rows; a bad manifest is bad input.
#include <string>

#include "tools/cli_fixture.h"

namespace {

using edgefit_cli_test::CliE2eTest;
using edgefit_cli_test::CliTest;
using edgefit_cli_test::RunResult;
using edgefit_cli_test::Slurp;
using edgefit_cli_test::kBalancerArm;
namespace fs = std::filesystem;

// A whole fit as a job: the release half (e2e); under the sanitizers
// BatchRowsAndMergeFlags and BatchShardsSplitTheRows run jobs that fail.
TEST_F(CliE2eTest, BatchRunsEveryJobAndReportsTheFailedOne) {
  ASSERT_EQ(Run("scan --urdf=" + kBalancerArm + " --scanners=2 --out=" + Path("arm.ptx") +
                " --truth=" + Path("truth.json"))
                .exit_code,
            0);
  // Relative paths are taken from the manifest's folder.
  const std::string manifest = Write("jobs.csv",
                                     "name,urdf,scan,out,options\n"
                                     "arm," +
                                         kBalancerArm +
                                         ",arm.ptx,arm_result.json,--truth=truth.json\n"
                                         "# a comment line\n"
                                         "lost," +
                                         kBalancerArm + ",none.ptx,lost_result.json,\n");
  const RunResult r = Run("batch --manifest=" + manifest);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // one job failed
  EXPECT_NE(r.out.find("[1/2] arm: ok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[2/2] lost: FAILED (exit 2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("none.ptx"), std::string::npos) << r.out;  // the job's error line
  EXPECT_NE(r.out.find("2 of 2 jobs: 1 done (0 not ok), 1 failed"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(Path("arm_result.json")));
  EXPECT_NE(Slurp(Path("arm_result.json")).find("\"errors\""), std::string::npos);  // --truth
  EXPECT_FALSE(fs::exists(Path("lost_result.json")));
  // The failed job leaves its record beside its output, for --merge.
  EXPECT_NE(Slurp(Path("lost_result.json.failed")).find("exit 2: "), std::string::npos);

  // --merge: every row once, the failed one with its error, the rows to redo.
  const RunResult merged = Run("batch --manifest=" + manifest + " --merge --out_csv=" +
                               Path("merged.csv") + " --out_report=" + Path("merged.html"));
  EXPECT_EQ(merged.exit_code, 1) << merged.out << merged.err;
  EXPECT_NE(merged.out.find("| 0 | arm | ok |"), std::string::npos) << merged.out;
  EXPECT_NE(merged.out.find("| 1 | lost | FAILED |"), std::string::npos) << merged.out;
  EXPECT_NE(merged.out.find("merge: 2 rows: 1 done (0 not ok), 1 failed, 0 missing"),
            std::string::npos)
      << merged.out;
  EXPECT_NE(merged.out.find("resubmit: edgefit batch --manifest=" + manifest + " --rows=1"),
            std::string::npos)
      << merged.out;
  EXPECT_NE(merged.out.find("Errors against the truth"), std::string::npos) << merged.out;
  const std::string csv = Slurp(Path("merged.csv"));
  EXPECT_NE(csv.find("0,arm,ok,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",joint_1,revolute,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("1,lost,FAILED,"), std::string::npos) << csv;
  EXPECT_NE(Slurp(Path("merged.html")).find("<td>lost</td><td>FAILED</td>"), std::string::npos);

  // The failed row again, now with its scan: done, and its record gone.
  fs::copy_file(Path("arm.ptx"), Path("none.ptx"));
  const RunResult again = Run("batch --manifest=" + manifest + " --rows=1");
  EXPECT_EQ(again.exit_code, 0) << again.out << again.err;
  EXPECT_NE(again.out.find("[1/1] lost: ok"), std::string::npos) << again.out;
  EXPECT_FALSE(fs::exists(Path("lost_result.json.failed")));
  const RunResult complete = Run("batch --manifest=" + manifest + " --merge");
  EXPECT_EQ(complete.exit_code, 0) << complete.out;
  EXPECT_NE(complete.out.find("merge: 2 rows: 2 done"), std::string::npos) << complete.out;
  EXPECT_EQ(complete.out.find("resubmit"), std::string::npos) << complete.out;
}

TEST_F(CliTest, BatchRowsAndMergeFlags) {
  std::string rows = "name,urdf,scan,out\n";
  for (int k = 0; k < 5; ++k) {
    rows +=
        "job" + std::to_string(k) + "," + kBalancerArm + ",missing.ptx,r" + std::to_string(k) + ".json\n";
  }
  const std::string manifest = Write("jobs.csv", rows);
  // --rows picks rows (ranges too), then the shards split them; the progress
  // says which job of how many and, after the first, the time left.
  const RunResult r =
      Run("batch --manifest=" + manifest + " --rows=4,1-2,3 --shard=1/2 --progress=always");
  EXPECT_NE(r.out.find("] job1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("] job3:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("] job2:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("] job4:"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find(" s] batch: job 1/2: row 1, job1\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s] batch: job 2/2, about "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s left: row 3, job3\n"), std::string::npos) << r.err;
  ExpectBadInput("batch --manifest=" + manifest + " --rows=5", "past the manifest's 5 rows");
  ExpectBadInput("batch --manifest=" + manifest + " --rows=2-a", "--rows: '2-a'");
  ExpectBadInput("batch --manifest=" + manifest + " --merge --rows=1", "--merge reads every row");
  ExpectBadInput("batch --manifest=" + manifest + " --out_csv=" + Path("x.csv"), "--merge");
  // Nothing run: every row missing, all five to resubmit.
  fs::remove(Path("r1.json.failed"));
  fs::remove(Path("r3.json.failed"));
  const RunResult merged = Run("batch --manifest=" + manifest + " --merge");
  EXPECT_EQ(merged.exit_code, 1);
  EXPECT_NE(merged.out.find("merge: 5 rows: 0 done (0 not ok), 0 failed, 5 missing"),
            std::string::npos)
      << merged.out;
  EXPECT_NE(merged.out.find("--rows=0-4"), std::string::npos) << merged.out;
}

TEST_F(CliTest, BatchShardsSplitTheRows) {
  std::string rows = "name,urdf,scan,out\n";
  for (int k = 0; k < 5; ++k) {
    rows +=
        "job" + std::to_string(k) + "," + kBalancerArm + ",missing.ptx,r" + std::to_string(k) + ".json\n";
  }
  const std::string manifest = Write("jobs.csv", rows);
  const RunResult first = Run("batch --manifest=" + manifest + " --shard=0/2");
  const RunResult second = Run("batch --manifest=" + manifest + " --shard=1/2");
  for (int k = 0; k < 5; ++k) {
    const std::string job = "] job" + std::to_string(k) + ":";
    EXPECT_EQ(first.out.find(job) != std::string::npos, k % 2 == 0) << first.out;
    EXPECT_EQ(second.out.find(job) != std::string::npos, k % 2 == 1) << second.out;
  }
  EXPECT_NE(first.out.find("shard 0/2, 3 of 5 jobs"), std::string::npos) << first.out;
  EXPECT_NE(second.out.find("shard 1/2, 2 of 5 jobs"), std::string::npos) << second.out;
}

TEST_F(CliTest, BatchBadManifest) {
  ExpectBadInput("batch", "--manifest is required");
  ExpectBadInput("batch --manifest=" + Path("none.csv"), "none.csv");
  const std::string no_out = Write("a.csv", "urdf,scan\nx.urdf,y.ptx\n");
  ExpectBadInput("batch --manifest=" + no_out, "a.csv:1: the header lacks the column 'out'");
  const std::string short_row = Write("b.csv", "urdf,scan,out\nx.urdf,y.ptx\n");
  ExpectBadInput("batch --manifest=" + short_row, "b.csv:2: 2 fields, the header has 3");
  const std::string owned = Write("c.csv", "urdf,scan,out,options\nx,y,z,--scan=w\n");
  ExpectBadInput("batch --manifest=" + owned, "belongs in its own column");
  const std::string good = Write("d.csv", "urdf,scan,out\nx,y,z\n");
  ExpectBadInput("batch --manifest=" + good + " --shard=2/2", "--shard=2/2");
  ExpectBadInput("batch --manifest=" + good + " --shard=one", "--shard must be i/N");
}

}  // namespace

namespace {

// A row with a cell's models runs edgefit cell; --merge reads its instances
// (each result inline, or from --out_dir) and their errors against the truth.
TEST_F(CliE2eTest, BatchRunsACellRowAndMergesItsInstances) {
  const std::string scene = Write(
      "scene.json", "{\"assets\": [\n {\"name\": \"a\", \"urdf\": \"" + kBalancerArm +
                        "\", \"joints\": \"joint_1=20deg,joint_2=-0.3\", \"base\": [-1.0, 0, 0]},\n"
                        " {\"name\": \"b\", \"urdf\": \"" + kBalancerArm +
                        "\", \"joints\": \"joint_1=-30deg,joint_2=0.2\", \"base\": [1.0, 0.3, 90]}]}\n");
  ASSERT_EQ(Run("scan --scene=" + scene + " --scanners=3 --spacing_mm=6 --seed=3 --out=" +
                Path("cell.e57") + " --truth=" + Path("truth.json"))
                .exit_code,
            0);
  Write("models.json",
        "{\"models\": [{\"name\": \"arm\", \"urdf\": \"" + kBalancerArm + "\", \"count\": 2}]}\n");
  const std::string manifest =
      Write("jobs.csv",
            "name,models,scan,out,options\n"
            "cell_inline,models.json,cell.e57,cell.json,--truth=truth.json\n"
            "cell_dir,models.json,cell.e57,cell_dir.json,--truth=truth.json --out_dir=instances\n");
  fs::create_directories(Path("instances"));
  const RunResult r = Run("batch --manifest=" + manifest);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const RunResult merged = Run("batch --manifest=" + manifest + " --merge --out_csv=" + Path("m.csv"));
  EXPECT_EQ(merged.exit_code, 0) << merged.out;
  for (const char* row : {"| 0 | cell_inline | ok |", "| 1 | cell_dir | ok |"}) {
    EXPECT_NE(merged.out.find(row), std::string::npos) << merged.out;
  }
  EXPECT_NE(merged.out.find("2 instances, 2 ok"), std::string::npos) << merged.out;
  // Both arms' joints, from each row: 2 rows x 2 instances x 2 independent joints.
  EXPECT_NE(merged.out.find("| 8 | "), std::string::npos) << merged.out;
  const std::string csv = Slurp(Path("m.csv"));
  EXPECT_NE(csv.find(",arm_1/joint_1,revolute,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",arm_2/joint_2,revolute,"), std::string::npos) << csv;
  ExpectBadInput("batch --manifest=" + Write("both.csv", "name,urdf,models,scan,out\n"
                                                          "x," + kBalancerArm + ",models.json,c.e57,o.json\n"),
                 "give a 'urdf' (a fit) or a 'models' (a cell), one of them");
}

}  // namespace
