// edgefit report: the HTML report of a fit from its result.json, whose
// "inputs" (written by edgefit fit) name the model and the scans it read;
// or of a bench from its runs (edgefit bench --out_json).
//   edgefit report --result=result.json --out=report.html
//   edgefit report --bench=runs.json --out=bench.html
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/bench/bench_tables.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/report/fit_report.h"
#include "fit_result_file.h"

DEFINE_string(bench, "",
              "report: the runs of edgefit bench (its --out_json); several files (the shards "
              "of one bench) as a comma list.");

namespace edgefit::tools {
namespace {

using nlohmann::json;

// The fit's model, joint values, base and station corrections from result.json.
Status ReadFit(const json& result, const std::string& path, KinematicModel* model,
               std::vector<double>* q, Pose* T_world_base, std::vector<Pose>* corrections,
               std::vector<std::string>* scans) {
  EDGEFIT_RETURN_IF_ERROR(ReadFittedModel(result, path, model, q, T_world_base));
  const json& inputs = result["inputs"];
  if (!inputs.contains("scan") || !inputs["scan"].is_array() || inputs["scan"].empty()) {
    return Status::Error(path + ": inputs.scan missing");
  }
  corrections->clear();
  if (result.contains("stations") && result["stations"].value("aligned", false)) {
    for (const json& c : result["stations"].value("corrections", json::array())) {
      Pose T;
      EDGEFIT_RETURN_IF_ERROR(
          PoseFromRows(c.value("T_correction", json()), path + ": stations.corrections", &T));
      corrections->push_back(T);
    }
  }
  for (const json& s : inputs["scan"]) {
    if (!s.is_string()) return Status::Error(path + ": inputs.scan holds a non-string");
    scans->push_back(s.get<std::string>());
  }
  return Status::Ok();
}

// The bench's tables and plots from its saved runs: one file, or the
// shards' files of a bench run as a Slurm array, their runs joined.
int RunBenchReport(const Command& command) {
  json runs = json::array();
  for (const std::string& path : SplitList(FLAGS_bench)) {
    std::string text;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadFileToString(path, &text));
    const json part = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!part.is_array()) {
      return BadInput(command, path + ": not the runs of edgefit bench --out_json (a JSON array)");
    }
    if (part.empty()) continue;  // a shard without scans
    const Status valid = CheckBenchRuns(part);
    if (!valid.ok()) return BadInput(command, path + ": " + valid.message());
    runs.insert(runs.end(), part.begin(), part.end());
  }
  if (runs.empty()) return BadInput(command, "--bench: no runs in " + FLAGS_bench);
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, WriteTablesReport(BenchReport(runs, "edgefit bench, runs read from " + FLAGS_bench),
                                 FLAGS_out));
  for (const Table& table : BenchTables(runs)) std::printf("%s", MarkdownTable(table).c_str());
  std::printf("\nreport: %s\n", FLAGS_out.c_str());
  return 0;
}

int RunReport(const Command& command) {
  if (FLAGS_result.empty() == FLAGS_bench.empty()) {
    return BadInput(command, "give one of --result (a fit) and --bench (a bench's runs)");
  }
  if (FLAGS_out.empty()) return BadInput(command, "--out is required");
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputPaths({FLAGS_out}));
  if (!FLAGS_bench.empty()) return RunBenchReport(command);
  FitReportOptions options;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckFitReportScripts(options));
  std::string text;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadFileToString(FLAGS_result, &text));
  const json result = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (result.is_discarded()) return BadInput(command, FLAGS_result + ": not JSON");
  const json& fit_options = result.value("options", json::object());
  if (fit_options.is_object() && fit_options.value("w_high", json()).is_number()) {
    options.edges.w_high = fit_options["w_high"].get<double>();  // the edge map's Eq. (6)
  }
  KinematicModel model;
  std::vector<double> q;
  Pose T_world_base;
  std::vector<Pose> corrections;
  std::vector<std::string> scan_paths;
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, ReadFit(result, FLAGS_result, &model, &q, &T_world_base, &corrections, &scan_paths));
  ScanSet scans;
  for (const std::string& path : scan_paths) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadScans(path, ReadOptions(), &scans));
  }
  if (!corrections.empty() && corrections.size() != scans.scans.size()) {
    return BadInput(command, FLAGS_result + ": " + std::to_string(corrections.size()) +
                                 " station corrections for " + std::to_string(scans.scans.size()) +
                                 " scans");
  }
  Progress("report: the scan against the fitted model");
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, WriteFitReport(model, q, T_world_base, scans, corrections, result,
                              "edgefit fit: " + result["inputs"]["urdf"].get<std::string>(),
                              options, FLAGS_out, nullptr));
  std::printf("report: %s (each station's view: %s, ...)\n", FLAGS_out.c_str(),
              StationImagePath(FLAGS_out, 0).c_str());
  return 0;
}

}  // namespace

Command ReportCommand() {
  return {"report",
          "the HTML report of a fit from its result.json (the scan against the fitted model, "
          "every joint's verdict), or of a bench from its runs (tables, ablation plots)",
          "Usage:\n"
          "  edgefit report --result=result.json --out=report.html\n"
          "  edgefit report --bench=runs.json[,runs_1.json,...] --out=bench.html\n"
          "Example:\n"
          "  edgefit fit --urdf=assets/robot/robot.urdf --scan=robot.ptx --out=result.json\n"
          "  edgefit report --result=result.json --out=report.html",
          {"result", "bench", "out"},
          RunReport};
}

}  // namespace edgefit::tools
