#include "edgefit/model/joint_values.h"

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

// Sets one independent joint, checking that it exists and its limits hold.
Status SetJoint(const KinematicModel& model, const std::string& name, double value,
                std::vector<double>* q) {
  const int j = model.JointIndex(name);
  if (j < 0) return Status::Error("unknown joint '" + name + "'");
  const Joint& joint = model.joints()[j];
  if (!joint.IsIndependent()) {
    return Status::Error("joint '" + name + "' is " +
                         (joint.IsMoving() ? "driven by other joints (mimic or loop closure)"
                                           : "fixed") +
                         " and cannot be set");
  }
  if (!std::isfinite(value)) return Status::Error("joint '" + name + "': value is not finite");
  // Limits written with a few decimals: allow a hair of rounding.
  constexpr double kSlack = 1e-9;
  if (joint.has_limits && (value < joint.lower - kSlack || value > joint.upper + kSlack)) {
    return Status::Error("joint '" + name + "': " + std::to_string(value) +
                         " is outside its limits [" + std::to_string(joint.lower) + ", " +
                         std::to_string(joint.upper) + "]");
  }
  (*q)[j] = value;
  return Status::Ok();
}

// "0.5" -> 0.5, "-30deg" -> -0.5236, "250mm" -> 0.25.
bool ParseValueWithUnit(const std::string& text, double* value) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin) return false;
  const std::string unit(end);
  if (unit.empty()) {
    *value = v;
  } else if (unit == "deg") {
    *value = v * M_PI / 180.0;
  } else if (unit == "rad") {
    *value = v;
  } else if (unit == "mm") {
    *value = v * 1e-3;
  } else if (unit == "m") {
    *value = v;
  } else {
    return false;
  }
  return true;
}

Status ReadPostures(const std::string& path, nlohmann::ordered_json* postures) {
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  nlohmann::ordered_json doc =
      nlohmann::ordered_json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return Status::Error(path + ": not valid JSON");
  if (!doc.is_object() || !doc.contains("postures") || !doc["postures"].is_object()) {
    return Status::Error(path + ": expected {\"postures\": {\"name\": {\"joint\": value}}}");
  }
  *postures = doc["postures"];
  return Status::Ok();
}

}  // namespace

Status ParseNamedValues(const std::string& text,
                        std::vector<std::pair<std::string, double>>* values) {
  values->clear();
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    start = end + 1;
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    double value = 0.0;
    if (eq == std::string::npos || eq == 0 || !ParseValueWithUnit(item.substr(eq + 1), &value)) {
      values->clear();
      return Status::Error("--joints: '" + item +
                           "' is not name=value (value in rad or m, or with deg / mm)");
    }
    values->emplace_back(item.substr(0, eq), value);
  }
  return Status::Ok();
}

Status ParseJointAssignments(const std::string& text, const KinematicModel& model,
                             std::vector<double>* q) {
  std::vector<std::pair<std::string, double>> values;
  EDGEFIT_RETURN_IF_ERROR(ParseNamedValues(text, &values));
  for (const auto& [name, value] : values) {
    EDGEFIT_RETURN_IF_ERROR(SetJoint(model, name, value, q).WithContext("--joints"));
  }
  return Status::Ok();
}

Status LoadNamedPosture(const std::string& path, const std::string& name,
                        const KinematicModel& model, std::vector<double>* q) {
  nlohmann::ordered_json postures;
  EDGEFIT_RETURN_IF_ERROR(ReadPostures(path, &postures));
  if (!postures.contains(name)) {
    std::string known;
    for (const auto& item : postures.items()) known += (known.empty() ? "" : ", ") + item.key();
    return Status::Error(path + ": no posture '" + name + "' (has: " + known + ")");
  }
  const nlohmann::ordered_json& posture = postures[name];
  if (!posture.is_object()) return Status::Error(path + ": posture '" + name + "' is not an object");
  for (const auto& item : posture.items()) {
    if (!item.value().is_number()) {
      return Status::Error(path + ": posture '" + name + "': joint '" + item.key() +
                           "' is not a number");
    }
    EDGEFIT_RETURN_IF_ERROR(SetJoint(model, item.key(), item.value().get<double>(), q)
                                .WithContext(path + ": posture '" + name + "'"));
  }
  return Status::Ok();
}

Status ListPostures(const std::string& path, std::vector<std::string>* names) {
  nlohmann::ordered_json postures;
  EDGEFIT_RETURN_IF_ERROR(ReadPostures(path, &postures));
  names->clear();
  for (const auto& item : postures.items()) names->push_back(item.key());
  return Status::Ok();
}

}  // namespace edgefit
