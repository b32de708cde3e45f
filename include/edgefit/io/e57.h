// E57 (ASTM E2807, the 3D imaging exchange format every scanner vendor
// writes) reader and writer, on tinyxml2 for the XML section.
//
// Reading: every /data3D scan of the file, its pose (quaternion and
// translation) as T_world_scanner, its points in the scanner frame. Fields:
// cartesianX/Y/Z or sphericalRange/Azimuth/Elevation (Float, ScaledInteger or
// Integer), cartesianInvalidState / sphericalInvalidState (non-zero = no
// point), intensity (kept as stored), colorRed/Green/Blue (mapped to 0..255
// through colorLimits), returnIndex (an organized scan keeps first returns,
// returnIndex 0, one per cell; an unorganized one keeps every return), and
// rowIndex/columnIndex: with both, the scan is organized on the grid of its
// indexBounds (or of the indices found, when the file has no indexBounds),
// rows = rowIndex - rowMinimum; without them it is an unorganized 1 x N cloud
// (organized() == false, no lattice). Other fields are decoded and skipped.
// Every page's CRC-32C is checked. The reader streams: memory is the scans
// it returns plus one 256 KiB chunk of pages and one packet per field.
//
// Writing: one /data3D scan per scan, in the scanner frame with its pose.
// Organized scans write every cell in cell order (column by column) with
// rowIndex, columnIndex and cartesianInvalidState (2 for a missing cell,
// coordinates 0); unorganized scans write their valid points. Coordinates
// and intensity as single-precision floats (the scan's own precision),
// colour as 8-bit integers. Deterministic: the same scans give the same bytes.
#ifndef EDGEFIT_IO_E57_H_
#define EDGEFIT_IO_E57_H_

#include <string>
#include <string_view>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Parses an E57 file held in memory; `name` prefixes messages. Appends the
// scans only on success.
Status ParseE57(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans);
// Reads an E57 file, streaming from disk.
Status ReadE57(const std::string& path, const ReadOptions& options, ScanSet* scans);

// Writes all scans to one E57 file, atomically.
Status WriteE57(const std::string& path, const ScanSet& scans);

}  // namespace edgefit

#endif  // EDGEFIT_IO_E57_H_
