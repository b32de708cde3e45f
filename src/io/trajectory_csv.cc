#include "edgefit/io/trajectory_csv.h"

#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

std::string Trim(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

}  // namespace

Status ReadTrajectoryCsv(const std::string& path, Trajectory* trajectory) {
  *trajectory = Trajectory();
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  std::stringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const std::vector<std::string> fields = Fields(trimmed);
    if (trajectory->joints.empty()) {
      std::set<std::string> seen;
      for (const std::string& name : fields) {
        if (name.empty()) return Status::Error(where + "an empty joint name in the header");
        if (!seen.insert(name).second) return Status::Error(where + "joint '" + name + "' twice in the header");
      }
      trajectory->joints = fields;
      continue;
    }
    if (fields.size() != trajectory->joints.size()) {
      return Status::Error(where + std::to_string(fields.size()) + " values for " +
                           std::to_string(trajectory->joints.size()) + " joints in the header");
    }
    std::vector<double> values;
    for (const std::string& field : fields) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(v)) {
        return Status::Error(where + "'" + field + "' is not a finite number");
      }
      values.push_back(v);
    }
    trajectory->waypoints.push_back(values);
  }
  if (trajectory->joints.empty()) return Status::Error(path + ": no header row of joint names");
  if (trajectory->waypoints.empty()) return Status::Error(path + ": no waypoint after the header");
  return Status::Ok();
}

}  // namespace edgefit
