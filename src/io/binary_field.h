// Private: scalar types of binary PCD / PLY records and how to decode them.
#ifndef EDGEFIT_SRC_IO_BINARY_FIELD_H_
#define EDGEFIT_SRC_IO_BINARY_FIELD_H_

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace edgefit {
namespace io_internal {

enum class ScalarType { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kInt64, kUInt64, kFloat32, kFloat64 };

inline int ScalarSize(ScalarType t) {
  switch (t) {
    case ScalarType::kInt8: case ScalarType::kUInt8: return 1;
    case ScalarType::kInt16: case ScalarType::kUInt16: return 2;
    case ScalarType::kInt32: case ScalarType::kUInt32: case ScalarType::kFloat32: return 4;
    default: return 8;
  }
}

// PLY type names (both the classic and the sized spelling); false if unknown.
inline bool PlyScalarType(const std::string& name, ScalarType* t) {
  static const struct { const char* name; ScalarType type; } kTypes[] = {
      {"char", ScalarType::kInt8},     {"int8", ScalarType::kInt8},
      {"uchar", ScalarType::kUInt8},   {"uint8", ScalarType::kUInt8},
      {"short", ScalarType::kInt16},   {"int16", ScalarType::kInt16},
      {"ushort", ScalarType::kUInt16}, {"uint16", ScalarType::kUInt16},
      {"int", ScalarType::kInt32},     {"int32", ScalarType::kInt32},
      {"uint", ScalarType::kUInt32},   {"uint32", ScalarType::kUInt32},
      {"float", ScalarType::kFloat32}, {"float32", ScalarType::kFloat32},
      {"double", ScalarType::kFloat64}, {"float64", ScalarType::kFloat64}};
  for (const auto& entry : kTypes) {
    if (name == entry.name) {
      *t = entry.type;
      return true;
    }
  }
  return false;
}

// PCD TYPE letter (F, U, I) and SIZE in bytes; false if unsupported.
inline bool PcdScalarType(char letter, int size, ScalarType* t) {
  if (letter == 'F' && size == 4) *t = ScalarType::kFloat32;
  else if (letter == 'F' && size == 8) *t = ScalarType::kFloat64;
  else if (letter == 'U' && size == 1) *t = ScalarType::kUInt8;
  else if (letter == 'U' && size == 2) *t = ScalarType::kUInt16;
  else if (letter == 'U' && size == 4) *t = ScalarType::kUInt32;
  else if (letter == 'U' && size == 8) *t = ScalarType::kUInt64;
  else if (letter == 'I' && size == 1) *t = ScalarType::kInt8;
  else if (letter == 'I' && size == 2) *t = ScalarType::kInt16;
  else if (letter == 'I' && size == 4) *t = ScalarType::kInt32;
  else if (letter == 'I' && size == 8) *t = ScalarType::kInt64;
  else return false;
  return true;
}

// Copies `size` bytes at p, reversing them for the other endianness.
inline void LoadBytes(const char* p, int size, bool swap, void* out) {
  char tmp[8];
  std::memcpy(tmp, p, static_cast<size_t>(size));
  if (swap) std::reverse(tmp, tmp + size);
  std::memcpy(out, tmp, static_cast<size_t>(size));
}

inline double DecodeScalar(const char* p, ScalarType t, bool swap) {
  switch (t) {
    case ScalarType::kInt8: { int8_t v; LoadBytes(p, 1, swap, &v); return v; }
    case ScalarType::kUInt8: { uint8_t v; LoadBytes(p, 1, swap, &v); return v; }
    case ScalarType::kInt16: { int16_t v; LoadBytes(p, 2, swap, &v); return v; }
    case ScalarType::kUInt16: { uint16_t v; LoadBytes(p, 2, swap, &v); return v; }
    case ScalarType::kInt32: { int32_t v; LoadBytes(p, 4, swap, &v); return v; }
    case ScalarType::kUInt32: { uint32_t v; LoadBytes(p, 4, swap, &v); return v; }
    case ScalarType::kInt64: { int64_t v; LoadBytes(p, 8, swap, &v); return static_cast<double>(v); }
    case ScalarType::kUInt64: { uint64_t v; LoadBytes(p, 8, swap, &v); return static_cast<double>(v); }
    case ScalarType::kFloat32: { float v; LoadBytes(p, 4, swap, &v); return v; }
    case ScalarType::kFloat64: { double v; LoadBytes(p, 8, swap, &v); return v; }
  }
  return 0.0;
}

inline bool HostIsLittleEndian() {
  const uint16_t one = 1;
  uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_BINARY_FIELD_H_
