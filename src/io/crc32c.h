// Private: CRC-32C (Castagnoli, reflected polynomial 0x82F63B78, initial and
// final XOR 0xFFFFFFFF), the checksum of every E57 page (ASTM E2807, 7.2).
#ifndef EDGEFIT_SRC_IO_CRC32C_H_
#define EDGEFIT_SRC_IO_CRC32C_H_

#include <cstddef>
#include <cstdint>

namespace edgefit {
namespace io_internal {

// CRC-32C of `size` bytes; the SSE4.2 instruction where the CPU has it, a
// table otherwise (same result).
uint32_t Crc32c(const void* data, size_t size);

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_CRC32C_H_
