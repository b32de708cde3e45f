// PLY reader and writer for unorganized clouds.
//
// Writing: the valid points of all scans in world coordinates, as float x y z,
// float intensity and, when every scan has colour, uchar red green blue;
// binary_little_endian or ascii. Reading: ascii, binary_little_endian and
// binary_big_endian; the vertex element's x y z (any scalar type), optional
// intensity (also "scalar_intensity", as CloudCompare names it) and
// red green blue. The result is one unorganized 1 x N scan (organized() ==
// false, no lattice) with identity pose: scanner frame = world frame.
#ifndef EDGEFIT_IO_PLY_H_
#define EDGEFIT_IO_PLY_H_

#include <string>
#include <string_view>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

Status ParsePly(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans);
Status ReadPly(const std::string& path, const ReadOptions& options, ScanSet* scans);

// Writes the valid points of all scans in world coordinates, atomically.
Status WritePly(const std::string& path, const ScanSet& scans, const WriteOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_IO_PLY_H_
