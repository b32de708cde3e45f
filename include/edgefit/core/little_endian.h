// Little-endian encoding of binary file fields whatever the host byte order
// (binary STL, binary PLY).
#ifndef EDGEFIT_CORE_LITTLE_ENDIAN_H_
#define EDGEFIT_CORE_LITTLE_ENDIAN_H_

#include <cstdint>
#include <cstring>
#include <string>

namespace edgefit {

inline void AppendUint32LE(uint32_t value, std::string* out) {
  for (int byte = 0; byte < 4; ++byte)
    out->push_back(static_cast<char>((value >> (8 * byte)) & 0xff));
}

// IEEE 754 single precision.
inline void AppendFloatLE(float value, std::string* out) {
  uint32_t bits = 0;
  static_assert(sizeof(bits) == sizeof(value), "float must be 32-bit");
  std::memcpy(&bits, &value, sizeof(bits));
  AppendUint32LE(bits, out);
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_LITTLE_ENDIAN_H_
