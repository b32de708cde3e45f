// Private: numbers appended as the shortest text that reads back exactly
// (std::to_chars), for the text writers; NaN as "nan".
#ifndef EDGEFIT_SRC_IO_NUMBER_TEXT_H_
#define EDGEFIT_SRC_IO_NUMBER_TEXT_H_

#include <charconv>
#include <cmath>
#include <string>
#include <type_traits>

namespace edgefit {
namespace io_internal {

template <typename T>
void AppendNumber(T value, std::string* out) {
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(value)) {
      *out += "nan";
      return;
    }
  }
  char buf[32];
  out->append(buf, std::to_chars(buf, buf + sizeof(buf), value).ptr);
}

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_NUMBER_TEXT_H_
