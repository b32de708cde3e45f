#include "batch_merge.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common_flags.h"
#include "edgefit/bench/bench_case.h"
#include "edgefit/core/angles.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/core/format.h"
#include "edgefit/report/tables_report.h"

namespace edgefit::tools {
namespace {

using nlohmann::json;

// object[key], or null when object is not an object or has no such key
// (result.json files come from anywhere: no lookup may throw).
const json& Get(const json& object, const std::string& key) {
  static const json kNull;
  if (!object.is_object()) return kNull;
  const auto it = object.find(key);
  return it == object.end() ? kNull : *it;
}

std::string Text(const json& value, const std::string& fallback = "") {
  return value.is_string() ? value.get<std::string>() : fallback;
}

// The results in the edgefit fit layout a row's output holds, each with a
// prefix for its joints: the fit's own (""), or each instance's of a cell
// ("robot_1/"; an instance written to --out_dir is read from there).
std::vector<std::pair<std::string, json>> FitResults(const json& output) {
  std::vector<std::pair<std::string, json>> results;
  if (Get(output, "quality").is_object()) {
    results.emplace_back("", output);
    return results;
  }
  const json& instances = Get(output, "instances");
  if (!instances.is_array()) return results;
  for (const json& instance : instances) {
    const json& result = Get(instance, "result");
    const std::string prefix = Text(Get(instance, "id"), "instance") + "/";
    if (result.is_object()) {
      results.emplace_back(prefix, result);
    } else if (result.is_string()) {
      std::ifstream in(result.get<std::string>());
      json read = json::parse(in, nullptr, /*allow_exceptions=*/false);
      if (read.is_object()) results.emplace_back(prefix, std::move(read));
    }
  }
  return results;
}

std::string StateText(const RowResult& row) {
  switch (row.state) {
    case RowState::kDone: return row.ok ? "ok" : "not ok";
    case RowState::kFailed: return "FAILED";
    case RowState::kMissing: return "missing";
  }
  return "";
}

// The verdicts of a done row's joints, "5 ok, 1 ambiguous".
std::string Verdicts(const RowResult& row) {
  if (row.state != RowState::kDone) return "-";
  std::map<std::string, int> counts;
  for (const auto& [prefix, result] : FitResults(row.result)) {
    const json& statuses = Get(result, "joint_status");
    if (!statuses.is_object()) continue;
    for (const auto& [joint, status] : statuses.items()) {
      const std::string verdict = Text(Get(status, "verdict"));
      if (!verdict.empty()) ++counts[verdict];
    }
  }
  std::string text;
  for (const auto& [verdict, n] : counts) {
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + verdict;
  }
  return text.empty() ? "-" : text;
}

// A done row's errors against a truth (--truth): joints, revolute [deg]
// and prismatic [mm] by the results' joint_types, bases and tool tips [mm].
// False when it has none.
bool TruthErrors(const RowResult& row, std::vector<double>* revolute,
                 std::vector<double>* prismatic, std::vector<double>* base,
                 std::vector<double>* tip) {
  if (row.state != RowState::kDone) return false;
  bool any = false;
  for (const auto& [prefix, result] : FitResults(row.result)) {
    const json& e = Get(result, "errors");
    const json& errors = Get(e, "joints");
    if (!errors.is_object()) continue;
    any = true;
    const json& types = Get(result, "joint_types");
    const json& status = Get(result, "joint_status");
    for (const auto& [joint, error] : errors.items()) {
      const std::string type = Text(Get(types, joint));
      const std::string verdict = Text(Get(Get(status, joint), "verdict"));
      // Dependent joints, unobservable ones (by convention) and results
      // without joint types are not scored.
      if (!error.is_number() || type.empty() || verdict.empty() || verdict == "unobservable") {
        continue;
      }
      if (type == "prismatic") {
        prismatic->push_back(1e3 * error.get<double>());
      } else {
        revolute->push_back(error.get<double>() / kDeg);
      }
    }
    if (Get(e, "base_translation_m").is_number()) {
      base->push_back(1e3 * Get(e, "base_translation_m").get<double>());
    }
    if (Get(e, "tool_tip_m").is_number()) tip->push_back(1e3 * Get(e, "tool_tip_m").get<double>());
  }
  return any;
}

double MaxOf(const std::vector<double>& values) {
  double m = std::numeric_limits<double>::quiet_NaN();
  for (const double v : values) m = std::isnan(m) ? v : std::max(m, v);
  return m;
}

// "3,5-7" for rows 3, 5, 6, 7.
std::string RowRanges(const std::vector<int>& rows) {
  std::string text;
  for (size_t k = 0; k < rows.size();) {
    size_t end = k;
    while (end + 1 < rows.size() && rows[end + 1] == rows[end] + 1) ++end;
    text += (text.empty() ? "" : ",") + std::to_string(rows[k]) +
            (end > k ? "-" + std::to_string(rows[end]) : "");
    k = end + 1;
  }
  return text;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string MergedCsv(const std::vector<RowResult>& rows) {
  std::ostringstream csv;
  csv << "row,name,status,seconds,joint,type,value,verdict,std,error,message\n";
  for (const RowResult& row : rows) {
    const std::string head = std::to_string(row.job->row) + "," + CsvField(row.job->name) + "," +
                             StateText(row) + "," +
                             (std::isnan(row.seconds) ? "" : FormatNumber("%.3f", row.seconds)) + ",";
    const std::vector<std::pair<std::string, json>> results =
        row.state == RowState::kDone ? FitResults(row.result)
                                     : std::vector<std::pair<std::string, json>>();
    size_t lines = 0;
    auto number = [](const json& v) {
      return v.is_number() ? FormatNumber("%.9g", v.get<double>()) : std::string();
    };
    for (const auto& [prefix, result] : results) {
      const json& joints = Get(result, "joints");
      if (!joints.is_object()) continue;
      const json& types = Get(result, "joint_types");
      const json& status = Get(result, "joint_status");
      const json& errors = Get(Get(result, "errors"), "joints");
      for (const auto& [joint, value] : joints.items()) {
        const json& st = Get(status, joint);
        csv << head << CsvField(prefix + joint) << "," << Text(Get(types, joint)) << ","
            << number(value) << "," << Text(Get(st, "verdict"), "dependent") << ","
            << number(Get(st, "std")) << "," << number(Get(errors, joint)) << ","
            << CsvField(row.message) << "\n";
        ++lines;
      }
    }
    if (lines == 0) csv << head << ",,,,,," << CsvField(row.message) << "\n";
  }
  return csv.str();
}

}  // namespace

RowResult ReadRow(const Job& job) {
  RowResult row;
  row.job = &job;
  if (std::filesystem::exists(job.out)) {
    std::ifstream in(job.out);
    row.result = json::parse(in, nullptr, /*allow_exceptions=*/false);
    const bool fit = Get(row.result, "quality").is_object();
    const bool cell = Get(row.result, "instances").is_array() && Get(row.result, "ok").is_boolean();
    if (!fit && !cell) {
      row.state = RowState::kFailed;
      row.message = "unreadable result: " + job.out + " is not the output of edgefit fit or cell";
      return row;
    }
    row.state = RowState::kDone;
    if (fit) {
      const json& quality = Get(row.result, "quality");
      row.ok = Get(quality, "ok").is_boolean() && Get(quality, "ok").get<bool>();
      row.message = Text(Get(quality, "message"));
    } else {
      // A cell: ok when every model's count is met and every instance ok.
      const json& instances = Get(row.result, "instances");
      size_t ok = 0;
      std::string first_not_ok;
      for (const json& instance : instances) {
        const bool instance_ok = Get(instance, "ok").is_boolean() && Get(instance, "ok").get<bool>();
        ok += instance_ok;
        if (!instance_ok && first_not_ok.empty()) {
          first_not_ok = Text(Get(instance, "id")) + ": " + Text(Get(instance, "message"));
        }
      }
      const bool counts_met = Get(row.result, "ok").get<bool>();
      row.ok = counts_met && ok == instances.size();
      row.message = std::to_string(instances.size()) + " instances, " + std::to_string(ok) +
                    " ok" + (counts_met ? "" : "; a model's count was not met") +
                    (first_not_ok.empty() ? "" : "; " + first_not_ok);
    }
    const json& total = Get(Get(row.result, "timing_s"), "total");
    if (total.is_number()) {
      row.seconds = total.get<double>();
    }
    return row;
  }
  std::ifstream failure(FailureRecordPath(job));
  if (failure) {
    row.state = RowState::kFailed;
    std::getline(failure, row.message);
    row.message = Trim(row.message);
    return row;
  }
  row.message = "no " + job.out + " (not run, or stopped before it ended)";
  return row;
}

int MergeBatch(const Command& command, const std::string& manifest, const std::vector<Job>& jobs) {
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputPaths({FLAGS_out_csv, FLAGS_out_report}));
  std::vector<RowResult> rows;
  for (const Job& job : jobs) rows.push_back(ReadRow(job));

  bool any_errors = false;
  for (const RowResult& row : rows) {
    std::vector<double> r, p, b, t;
    any_errors = any_errors || TruthErrors(row, &r, &p, &b, &t);
  }
  Table table;
  table.heading = "Jobs";
  table.header = {"row", "name", "status", "time [s]", "joints"};
  if (any_errors) table.header.insert(table.header.end(), {"max error [deg]", "max error [mm]"});
  table.header.insert(table.header.end(), {"message", "out"});
  std::vector<double> revolute, prismatic, base, tip;
  int done = 0, not_ok = 0, failed = 0, missing = 0;
  std::vector<int> redo;
  Table redo_table;
  redo_table.heading = "Missing or failed";
  redo_table.header = {"row", "name", "status", "why"};
  for (const RowResult& row : rows) {
    std::vector<std::string> cells = {std::to_string(row.job->row), row.job->name, StateText(row),
                                      std::isnan(row.seconds) ? "-" : FormatNumber("%.1f", row.seconds),
                                      Verdicts(row)};
    if (any_errors) {
      std::vector<double> r, p;
      TruthErrors(row, &r, &p, &base, &tip);
      cells.push_back(!r.empty() ? FormatNumber("%.4f", MaxOf(r)) : "-");
      cells.push_back(!p.empty() ? FormatNumber("%.3f", MaxOf(p)) : "-");
      revolute.insert(revolute.end(), r.begin(), r.end());
      prismatic.insert(prismatic.end(), p.begin(), p.end());
    }
    cells.push_back(row.message.empty() ? "-" : row.message);
    cells.push_back(row.job->out);
    table.rows.push_back(cells);
    done += row.state == RowState::kDone;
    not_ok += row.state == RowState::kDone && !row.ok;
    failed += row.state == RowState::kFailed;
    missing += row.state == RowState::kMissing;
    if (row.state != RowState::kDone) {
      redo.push_back(row.job->row);
      redo_table.rows.push_back(
          {std::to_string(row.job->row), row.job->name, StateText(row), row.message});
    }
  }
  std::vector<Table> tables = {table};
  if (any_errors) {
    Table errors;
    errors.heading = "Errors against the truth (rows fitted with --truth)";
    errors.header = {"joints", "revolute mean", "p95", "max [deg]", "joints", "prismatic mean",
                     "p95", "max [mm]", "base mean [mm]", "tool tip mean [mm]"};
    // "n", "mean", "p95", "max" of the errors, dashes for none.
    auto stats = [](const std::vector<double>& e, const char* format) {
      if (e.empty()) return std::vector<std::string>{"0", "-", "-", "-"};
      const ErrorStats s = SummarizeErrors(e);
      return std::vector<std::string>{std::to_string(e.size()), FormatNumber(format, s.mean),
                                      FormatNumber(format, s.p95), FormatNumber(format, s.max)};
    };
    std::vector<std::string> cells = stats(revolute, "%.4f");
    for (const std::string& c : stats(prismatic, "%.3f")) cells.push_back(c);
    cells.push_back(base.empty() ? "-" : FormatNumber("%.3f", SummarizeErrors(base).mean));
    cells.push_back(tip.empty() ? "-" : FormatNumber("%.3f", SummarizeErrors(tip).mean));
    errors.rows.push_back(cells);
    errors.note = "Joints the fit called unobservable are left out (reported by convention).";
    tables.push_back(errors);
  }
  if (!redo.empty()) tables.push_back(redo_table);

  const std::string summary = "merge: " + std::to_string(rows.size()) + " rows: " +
                              std::to_string(done) + " done (" + std::to_string(not_ok) +
                              " not ok), " + std::to_string(failed) + " failed, " +
                              std::to_string(missing) + " missing";
  std::vector<std::string> lines = {summary};
  if (!redo.empty()) {
    const std::string list = RowRanges(redo);
    lines.push_back("resubmit: edgefit batch --manifest=" + manifest + " --rows=" + list);
    lines.push_back("on Slurm: sbatch --array=0-" + std::to_string(redo.size() - 1) +
                    " scripts/slurm/batch.sbatch " + manifest + " --rows=" + list);
  }
  for (const Table& t : tables) std::printf("%s", MarkdownTable(t).c_str());
  std::printf("\n");
  for (const std::string& line : lines) std::printf("%s\n", line.c_str());

  std::vector<std::string> written;
  auto write = [&](const std::string& path, const std::string& content) {
    const Status status = WriteStringAtomically(path, content);
    if (status.ok()) {
      written.push_back(path);
      return true;
    }
    for (const std::string& w : written) std::remove(w.c_str());
    BadInput(command, status);
    return false;
  };
  if (!FLAGS_out_csv.empty() && !write(FLAGS_out_csv, MergedCsv(rows))) return kExitBadInput;
  if (!FLAGS_out_report.empty()) {
    TablesReport report;
    report.title = "edgefit batch: " + manifest;
    report.lines = lines;
    report.tables = tables;
    if (!write(FLAGS_out_report, TablesReportPage(report))) return kExitBadInput;
  }
  return redo.empty() ? kExitOk : kExitInternal;
}

}  // namespace edgefit::tools
