// Mixed pixels on the scan lattice: a beam whose footprint falls on a
// foreground edge and the surface behind it returns a range between the
// two (an energy-weighted mean), a point on neither surface. They sit
// exactly where the edges are, and pull links and edge weights off.
//
// A valid cell i is mixed along one of the four lines of its scan's grid
// through it (row, column, two diagonals) when, with neighbours a1, a2 on
// one side and b1, b2 on the other (a2, b2 two cells away):
//   - its range lies between r(a1) and r(b1), more than the tolerance from
//     each (a depth step across it), and
//   - it lies more than the tolerance off the surface of either side,
//     extrapolated linearly along the line (2 r(a1) - r(a2); r(a1) alone
//     when a2 is missing).
// A plane seen at a grazing angle is linear along every line, so its cells
// lie on the extrapolation from both sides and are kept; a corner between
// two faces keeps each cell on the face it belongs to. A mixed pixel on an
// edge is between the surfaces along every line that crosses the edge (3
// of the 4 unless the edge runs along a diagonal), while noise on a
// surface fakes a step along each line independently: asking for several
// lines keeps the noise out. A cell is a mixed pixel when it is mixed
// along min_lines lines, or along neighbour_lines beside such a cell (the
// rest of a band of mixed pixels across an edge).
#ifndef EDGEFIT_SCAN_MIXED_PIXELS_H_
#define EDGEFIT_SCAN_MIXED_PIXELS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct MixedPixelOptions {
  // Off both sides' surfaces and both neighbours' ranges by more than this
  // [m]. Five range noise sigmas of the scans edgefit is tested on (1 mm):
  // a linear extrapolation from two noisy ranges has about 2.4 sigma of
  // noise, so a cell on a surface is within 2 of its sigmas.
  double tolerance = 0.005;
  // ... or this many times the cell's spacing (range times the lattice's
  // step), when larger: on a curved surface a linear extrapolation misses
  // by more the coarser the grid. On an ideal scan of the demo robot at
  // 6 mm, 1.9 % of the cells were taken for mixed pixels with the fixed
  // tolerance alone, 0.23 % with 1.5 spacings (1.7 mm: 0.05 % either way).
  double tolerance_per_spacing = 1.5;
  // Lines (of 4) along which the cell must be mixed. On the raised bench
  // scene at 1.7 mm (edgefit edges --labels): 1 line found 66 % of the
  // labelled mixed pixels at precision 0.67 (mixed pixels alone) and 0.11
  // (every effect: dark and grazing surfaces are noisy); 3 lines 56 % at
  // 0.94, and 39 % at 0.83.
  int min_lines = 3;
  // ... or along this many, beside a cell mixed along min_lines (one of its
  // 8 neighbours); 0: none. The beam's footprint (3-5 mm at 2-10 m for a
  // FARO Focus class scanner) spans 2-3 cells at 1.7 mm, so an edge leaves
  // a band of mixed pixels whose ranges step from one surface to the other
  // almost linearly: a cell in the band lies on the extrapolation through
  // its neighbour in the band along most lines and is mixed along only one.
  // On a realistic scan of the bundled robot (every effect, jackets,
  // 1.7 mm; against its labels) min_lines 3 alone found 42 % of the
  // labelled mixed pixels at precision 0.88 (52 % at 0.98 around the gun's
  // electrode); with 1 line beside them 55 % at 0.63 (72 % at 0.88 there),
  // a 1-line test everywhere 65 % at 0.14 (noisy dark and grazing cells).
  int neighbour_lines = 1;

  bool IsValid(std::string* error) const;
};

// mixed[i] = 1 for the mixed pixels of `scan` (cell order), 0 elsewhere;
// all 0 for an unorganized scan. Deterministic for any thread count.
std::vector<uint8_t> FindMixedPixels(const OrganizedScan& scan, const MixedPixelOptions& options);

// The same for every scan of `scans` (per scan, per cell: a CellMask of
// the searches, which take them as missing); *count counts them.
std::vector<std::vector<uint8_t>> FindMixedPixels(const ScanSet& scans,
                                                  const MixedPixelOptions& options, size_t* count);

// The mixed pixels at the silhouette of a known object (a fitted machine),
// which the tests above miss where a band of them ramps evenly from the
// object to what lies behind it: a cell not of the object is one when,
// along a row, a column or a diagonal of its grid, a cell of the object
// within `radius` cells on one side lies nearer than it, and on the other
// side the surface behind (two cells, k and k + 1 away for some k up to
// `radius`, not of the object), extrapolated back to the cell, lies
// farther, each by more than the tolerance above. A surface between the
// object and what is behind keeps all but such a band of `radius` cells at
// its edges. `object`: per scan, per cell, nonzero for the object's
// cells; sets (*mixed)[s][c] = 1 for those found (same shape) and returns
// how many it set that were not set.
size_t MarkSilhouetteMixedPixels(const ScanSet& scans, const std::vector<std::vector<uint8_t>>& object,
                                 const MixedPixelOptions& options, int radius,
                                 std::vector<std::vector<uint8_t>>* mixed);

// A copy of `scans` with every mixed pixel a missing cell; *removed counts
// them.
ScanSet WithoutMixedPixels(const ScanSet& scans, const MixedPixelOptions& options, size_t* removed);

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_MIXED_PIXELS_H_
