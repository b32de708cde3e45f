// PTX (Leica ASCII exchange format) reader and writer.
//
// Per scan: line 1 and 2 = grid sizes (nominally columns, rows); line 3 =
// scanner position; lines 4-6 = scanner X, Y, Z axes; lines 7-10 = a 4x4
// matrix in row-vector convention (translation on line 10), i.e. the rows of
// T_world_scanner^T; then one line `x y z intensity [r g b]` per cell, points
// in the scanner frame, `0 0 0` for a missing return. Files hold many scans.
// World = matrix applied to the points, as CloudCompare does; the position
// and axis lines are checked for being numbers but not used.
//
// The grid layout (which size is which, which index runs fastest) is detected
// from the data (ptx_layout.h). Parsing is a hand-written line scanner over
// the mapped file with fast_float, OpenMP-parallel over line blocks.
#ifndef EDGEFIT_IO_PTX_H_
#define EDGEFIT_IO_PTX_H_

#include <functional>
#include <string>
#include <string_view>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Parses PTX text; `name` (the file) prefixes messages and fills `sources`.
// Appends the scans to `scans` only on success. `parsed` (optional) is
// told, after each scan's points, where the text still to be read begins.
Status ParsePtx(std::string_view content, const std::string& name, const ReadOptions& options,
                ScanSet* scans, const std::function<void(const char*)>& parsed = nullptr);
// Reads a PTX file: mapped (core/mapped_file.h), each scan's text let go
// once its points are parsed, so that the peak holds one scan's text.
Status ReadPtx(const std::string& path, const ReadOptions& options, ScanSet* scans);

// Writes organized scans as PTX, atomically. Cells go in each scan's file
// order: column by column (header: columns, rows) for kColumnMajor; row by
// row (header: rows, columns, so line 2 stays the run length) for kRowMajor.
// Floats are printed in shortest round-trip form.
Status WritePtx(const std::string& path, const ScanSet& scans);

}  // namespace edgefit

#endif  // EDGEFIT_IO_PTX_H_
