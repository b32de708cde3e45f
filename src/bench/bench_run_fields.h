// Fields of the bench's runs (the JSON objects of `edgefit bench
// --out_json`), read the same way by its tables and its plots. The runs are
// checked first (CheckBenchRuns).
#ifndef EDGEFIT_BENCH_BENCH_RUN_FIELDS_H_
#define EDGEFIT_BENCH_BENCH_RUN_FIELDS_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "edgefit/core/angles.h"
#include "edgefit/core/format.h"

namespace edgefit::bench_run {

using nlohmann::json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A number of a run; null (how JSON writes NaN) reads as NaN.
inline double Number(const json& object, const char* key) {
  const json& v = object.at(key);
  return v.is_number() ? v.get<double>() : kNaN;
}

inline bool IsPrismatic(const json& run, const std::string& joint) {
  const json& p = run["prismatic_joints"];
  return std::find(p.begin(), p.end(), joint) != p.end();
}

// A setting's value as text ("%g" for numbers, off/on for booleans).
inline std::string SettingText(const json& value) {
  if (value.is_boolean()) return value.get<bool>() ? "on" : "off";
  if (value.is_number()) return FormatNumber("%g", value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  return "-";
}

// The observable joints' errors of a run, revolute [deg] and prismatic [mm].
inline void PoolErrors(const json& run, std::vector<double>* revolute,
                       std::vector<double>* prismatic) {
  for (const auto& [joint, value] : run["joint_errors"].items()) {
    if (!value.is_number()) continue;
    if (IsPrismatic(run, joint)) {
      prismatic->push_back(1e3 * value.get<double>());
    } else {
      revolute->push_back(value.get<double>() / kDeg);
    }
  }
}

}  // namespace edgefit::bench_run

#endif  // EDGEFIT_BENCH_BENCH_RUN_FIELDS_H_
