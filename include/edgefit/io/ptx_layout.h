// PTX grid layout detection. The header of a PTX scan holds two sizes (line 1,
// line 2), nominally columns then rows, and the points follow column by
// column. Vendors disagree on both the order of the two sizes and on which
// grid index runs fastest in the file, so the layout is read off the data:
//
//  - inner size m (points per run of the fast index) is the candidate, line 1
//    or line 2, for which points f and f+m are angular neighbours: the median
//    angle between their directions is the smaller one;
//  - the fast index is elevation (runs are columns) when consecutive points
//    differ more in elevation than in azimuth * cos(elevation), otherwise the
//    runs are rows.
#ifndef EDGEFIT_IO_PTX_LAYOUT_H_
#define EDGEFIT_IO_PTX_LAYOUT_H_

#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct PtxLayout {
  int rows = 0;  // grid rows (elevation)
  int cols = 0;  // grid columns (azimuth)
  // kColumnMajor: file index = col * rows + row (runs are columns);
  // kRowMajor: file index = row * cols + col (runs are rows).
  OrganizedScan::FileOrder order = OrganizedScan::FileOrder::kColumnMajor;
};

// `in_file_order` holds the block's points with cell index == file index
// (any rows x cols shape with the right size). `header_first` and
// `header_second` are the sizes on header lines 1 and 2. Falls back to the
// standard layout (rows = line 2, column by column) when the data cannot tell.
PtxLayout DetectPtxLayout(const OrganizedScan& in_file_order, int header_first,
                          int header_second);

// The standard layout for the two header sizes (no detection).
PtxLayout StandardPtxLayout(int header_first, int header_second);

// Rearranges a scan held in file order into the grid of `layout` (moves the
// data when nothing changes). Keeps pose, intensity and colours.
OrganizedScan ApplyPtxLayout(OrganizedScan in_file_order, const PtxLayout& layout);

}  // namespace edgefit

#endif  // EDGEFIT_IO_PTX_LAYOUT_H_
