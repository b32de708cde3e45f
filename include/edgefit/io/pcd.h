// PCD (Point Cloud Library) reader and writer, one scan per file.
//
// Organized when HEIGHT > 1: WIDTH columns x HEIGHT rows stored row by row
// (FileOrder::kRowMajor). VIEWPOINT tx ty tz qw qx qy qz is T_world_scanner;
// points are in the scanner frame, as PCL keeps them; NaN = missing.
// HEIGHT == 1 reads as an unorganized 1 x N cloud. FIELDS must hold x y z;
// intensity and rgb / rgba (packed 0x00RRGGBB) are used when present, other
// fields skipped. DATA ascii, binary and binary_compressed (PCL's LZF layout,
// field by field).
#ifndef EDGEFIT_IO_PCD_H_
#define EDGEFIT_IO_PCD_H_

#include <string>
#include <string_view>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Parses a PCD file held in memory; `name` prefixes messages. Appends the scan.
Status ParsePcd(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans);
Status ReadPcd(const std::string& path, const ReadOptions& options, ScanSet* scans);

// Writes one scan (x y z intensity [rgb as U32], row by row, NaN for missing),
// ascii or binary per options.binary, atomically.
Status WritePcd(const std::string& path, const OrganizedScan& scan, const WriteOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_IO_PCD_H_
