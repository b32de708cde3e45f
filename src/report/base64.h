// Base64 (RFC 4648, with padding) of raw bytes: how the report embeds its
// binary arrays (points, distances, meshes) in the HTML page, which the
// page decodes into typed arrays.
#ifndef EDGEFIT_REPORT_BASE64_H_
#define EDGEFIT_REPORT_BASE64_H_

#include <cstddef>
#include <string>
#include <vector>

namespace edgefit {

std::string Base64(const void* data, size_t bytes);

template <class T>
std::string Base64(const std::vector<T>& values) {
  return Base64(values.data(), values.size() * sizeof(T));
}

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_BASE64_H_
