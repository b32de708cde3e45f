// One number as text through a printf format ("%.4f", "%g"): the tables and
// reports' cells.
#ifndef EDGEFIT_CORE_FORMAT_H_
#define EDGEFIT_CORE_FORMAT_H_

#include <cstdio>
#include <string>

namespace edgefit {

inline std::string FormatNumber(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_FORMAT_H_
