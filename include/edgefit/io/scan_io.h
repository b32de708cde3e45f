// Scan files by extension: .ptx (ptx.h), .pcd (pcd.h), .ply (ply.h), .e57 (e57.h).
// The one entry point the command line uses to load and save ScanSets.
#ifndef EDGEFIT_IO_SCAN_IO_H_
#define EDGEFIT_IO_SCAN_IO_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Reads every scan of `path` and appends it to `scans` (nothing is appended
// on failure). Organized scans get their lattice estimated unless
// options.estimate_lattice is false. Fails with one line naming the file (and
// line, for text formats) on a missing, empty, malformed or truncated file, an
// unknown extension or a scan without valid points.
Status ReadScans(const std::string& path, const ReadOptions& options, ScanSet* scans);

// Writes `scans` to `path` atomically: PTX and E57 hold all scans (PTX the
// organized ones); PCD exactly one scan; PLY the valid points of all scans in
// world coordinates.
Status WriteScans(const std::string& path, const ScanSet& scans, const WriteOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_IO_SCAN_IO_H_
