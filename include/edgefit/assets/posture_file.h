// Named postures of a benchmark model (paper Sec. 7.3 uses three per model),
// stored as JSON: {"postures": {"name": {"joint_1": value, ...}, ...}} with
// radians for revolute and metres for prismatic joints, every independent
// joint listed. Dependent (loop-closure, mimic) joints are left out: they
// follow from ResolveDependentJoints.
#ifndef EDGEFIT_ASSETS_POSTURE_FILE_H_
#define EDGEFIT_ASSETS_POSTURE_FILE_H_

#include <string>
#include <utility>
#include <vector>

namespace edgefit {

struct NamedPosture {
  std::string name;
  std::vector<std::pair<std::string, double>> joint_values;  // in output order
};

// Deterministic text: postures and joints in the given order, "%.9g" numbers.
std::string FormatPosturesJson(const std::vector<NamedPosture>& postures);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_POSTURE_FILE_H_
