// Little-endian encoding of binary file fields whatever the host byte order
// (binary STL, binary PLY, E57).
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

// The unsigned integer of `bytes` (1..8) little-endian bytes at p.
inline uint64_t LoadUintLE(const uint8_t* p, int bytes) {
  uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

// Writes the low `bytes` (1..8) bytes of v little-endian at out.
inline void StoreUintLE(uint64_t v, int bytes, uint8_t* out) {
  for (int k = 0; k < bytes; ++k) out[k] = static_cast<uint8_t>(v >> (8 * k));
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_LITTLE_ENDIAN_H_
