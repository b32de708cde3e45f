#include "edgefit/io/joint_states.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <exception>

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
  values->clear();
  Status status = Status::Ok();
  try {
    status = Parse(YAML::LoadFile(path), values);
  } catch (const YAML::BadFile&) {
    status = Status::Error("cannot open the file");
  } catch (const std::exception& e) {  // yaml-cpp's parser and conversion errors
    status = Status::Error(std::string("not a joint_states YAML file: ") + e.what());
  }
  if (!status.ok()) {
    values->clear();
    return Status::Error(path + ": " + status.message());
  }
  return Status::Ok();
}

}  // namespace edgefit
