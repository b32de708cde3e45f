#include "batch_manifest.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace edgefit::tools {

namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace

std::string Trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}


Status ReadManifest(const std::string& path, int threads, std::vector<Job>* jobs) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open the manifest");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  auto resolve = [&folder](const std::string& p) {
    return std::filesystem::path(p).is_absolute() || folder.empty() ? p : (folder / p).string();
  };
  std::string line;
  std::map<std::string, size_t> column;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    if (Trim(line).empty() || Trim(line)[0] == '#') continue;
    if (line.find('"') != std::string::npos) {
      return Status::Error(where + "quoted fields are not supported (lists use ';')");
    }
    std::vector<std::string> fields = Split(line, ',');
    for (std::string& f : fields) f = Trim(f);
    if (column.empty()) {  // the header
      for (size_t k = 0; k < fields.size(); ++k) {
        static const char* kKnown[] = {"name", "urdf", "models", "attach", "scan", "out", "options"};
        if (std::find(std::begin(kKnown), std::end(kKnown), fields[k]) == std::end(kKnown)) {
          return Status::Error(where + "unknown column '" + fields[k] +
                               "' (name, urdf, models, attach, scan, out, options)");
        }
        column[fields[k]] = k;
      }
      if (column.count("urdf") == 0 && column.count("models") == 0) {
        return Status::Error(where + "the header lacks the column 'urdf' (or 'models')");
      }
      for (const char* required : {"scan", "out"}) {
        if (column.count(required) == 0) {
          return Status::Error(where + "the header lacks the column '" + required + "'");
        }
      }
      continue;
    }
    if (fields.size() != column.size()) {
      return Status::Error(where + std::to_string(fields.size()) + " fields, the header has " +
                           std::to_string(column.size()));
    }
    auto field = [&](const char* name) {
      return column.count(name) != 0 ? fields[column[name]] : std::string();
    };
    Job job;
    job.row = static_cast<int>(jobs->size());
    job.name = field("name").empty() ? "row " + std::to_string(job.row) : field("name");
    for (const char* required : {"scan", "out"}) {
      if (field(required).empty()) return Status::Error(where + "empty '" + required + "'");
    }
    if (field("urdf").empty() == field("models").empty()) {
      return Status::Error(where + "give a 'urdf' (a fit) or a 'models' (a cell), one of them");
    }
    job.out = resolve(field("out"));
    job.cell = !field("models").empty();
    job.args = {job.cell ? "cell" : "fit",
                job.cell ? "--models=" + resolve(field("models")) : "--urdf=" + resolve(field("urdf")),
                "--out=" + job.out};
    if (job.cell && !field("attach").empty()) {
      return Status::Error(where + "a cell's end effectors go in its models file, not 'attach'");
    }
    std::string scans;
    for (const std::string& scan : Split(field("scan"), ';')) {
      if (!Trim(scan).empty()) scans += (scans.empty() ? "" : ",") + resolve(Trim(scan));
    }
    job.args.push_back("--scan=" + scans);
    std::string attach;
    for (const std::string& a : Split(field("attach"), ';')) {
      if (!Trim(a).empty()) attach += (attach.empty() ? "" : ",") + resolve(Trim(a));
    }
    if (!attach.empty()) job.args.push_back("--attach=" + attach);
    std::istringstream options(field("options"));
    for (std::string option; options >> option;) {
      for (const char* owned : {"--urdf", "--models", "--scan", "--out=", "--attach"}) {
        if (option.rfind(owned, 0) == 0) {
          return Status::Error(where + "option '" + option + "' belongs in its own column");
        }
      }
      if (option.rfind("--", 0) != 0) {
        return Status::Error(where + "option '" + option + "' is not a --flag");
      }
      // Path-valued flags follow the manifest's folder too.
      for (const char* path_flag : {"--truth=", "--out_joint_states=", "--out_urdf=", "--out_ply=",
                                    "--out_background=", "--out_dir=", "--out_report="}) {
        const std::string prefix = path_flag;
        if (option.rfind(prefix, 0) == 0) option = prefix + resolve(option.substr(prefix.size()));
      }
      job.args.push_back(option);
    }
    if (threads > 0) job.args.push_back("--threads=" + std::to_string(threads));
    jobs->push_back(std::move(job));
  }
  if (column.empty()) return Status::Error(path + ": the manifest has no header row");
  return Status::Ok();
}

Status ParseRows(const std::string& text, int rows, std::vector<int>* selected) {
  selected->clear();
  if (text.empty()) {
    for (int k = 0; k < rows; ++k) selected->push_back(k);
    return Status::Ok();
  }
  std::vector<bool> taken(static_cast<size_t>(rows), false);
  for (const std::string& item : Split(text, ',')) {
    const std::string part = Trim(item);
    if (part.empty()) continue;
    const size_t dash = part.find('-', 1);
    const std::string first = part.substr(0, dash);
    const std::string last = dash == std::string::npos ? first : part.substr(dash + 1);
    char* end_a = nullptr;
    char* end_b = nullptr;
    const long a = std::strtol(first.c_str(), &end_a, 10);
    const long b = std::strtol(last.c_str(), &end_b, 10);
    if (first.empty() || last.empty() || *end_a != '\0' || *end_b != '\0' || a < 0 || b < a) {
      return Status::Error("--rows: '" + part + "' is not a row or a range of rows (3 or 10-12)");
    }
    if (b >= rows) {
      return Status::Error("--rows: row " + std::to_string(b) + " is past the manifest's " +
                           std::to_string(rows) + " rows (counted from 0)");
    }
    for (long k = a; k <= b; ++k) {
      if (!taken[static_cast<size_t>(k)]) selected->push_back(static_cast<int>(k));
      taken[static_cast<size_t>(k)] = true;
    }
  }
  if (selected->empty()) return Status::Error("--rows: no rows given");
  return Status::Ok();
}

std::string FailureRecordPath(const Job& job) { return job.out + ".failed"; }

}  // namespace edgefit::tools
