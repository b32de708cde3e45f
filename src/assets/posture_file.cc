#include "edgefit/assets/posture_file.h"

#include <sstream>

#include "edgefit/assets/urdf_writer.h"

namespace edgefit {

std::string FormatPosturesJson(const std::vector<NamedPosture>& postures) {
  std::ostringstream os;
  os << "{\n  \"postures\": {\n";
  for (size_t p = 0; p < postures.size(); ++p) {
    os << "    \"" << postures[p].name << "\": {";
    const auto& values = postures[p].joint_values;
    for (size_t k = 0; k < values.size(); ++k) {
      os << (k ? ", " : "") << "\"" << values[k].first
         << "\": " << FormatUrdfNumber(values[k].second);
    }
    os << "}" << (p + 1 < postures.size() ? "," : "") << "\n";
  }
  os << "  }\n}\n";
  return os.str();
}

}  // namespace edgefit
