#include "edgefit/io/joint_states.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "yaml_file.h"

namespace edgefit {
namespace {

Status Parse(const YAML::Node& root, std::vector<std::pair<std::string, double>>* values) {
  if (!root.IsMap() || !root["name"] || !root["position"]) {
    return Status::Error("not a joint_states message (no name and position lists)");
  }
  const YAML::Node names = root["name"], positions = root["position"];
  if (!names.IsSequence() || !positions.IsSequence() || names.size() != positions.size()) {
    return Status::Error("name and position must be lists of the same length");
  }
  for (size_t i = 0; i < names.size(); ++i) {
    const double value = positions[i].as<double>();
    if (!std::isfinite(value)) {
      return Status::Error("position of '" + names[i].as<std::string>() + "' is not finite");
    }
    values->emplace_back(names[i].as<std::string>(), value);
  }
  return Status::Ok();
}

}  // namespace

Status ReadJointStates(const std::string& path,
                       std::vector<std::pair<std::string, double>>* values) {
  return ReadYamlFile(path, "a joint_states YAML file", Parse, values);
}

std::string JointStatesYaml(const std::vector<std::pair<std::string, double>>& values,
                            const std::string& comment) {
  std::string text;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) text += "# " + line + "\n";
  std::string names, positions;
  for (const auto& [name, value] : values) {
    char number[32];
    std::snprintf(number, sizeof(number), "%.9g", value);
    names += (names.empty() ? "" : ", ") + name;
    positions += (positions.empty() ? "" : ", ") + std::string(number);
  }
  return text + "name: [" + names + "]\nposition: [" + positions + "]\nvelocity: []\neffort: []\n";
}

}  // namespace edgefit
