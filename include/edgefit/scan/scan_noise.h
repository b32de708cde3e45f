// The range noise of a scan set, measured on the scans themselves: a laser
// scanner's is about a millimetre at any range, a stereo camera's grows with
// the square of the range (a centimetre at 2-3 m). The fit's distance
// thresholds (gates, visibility tolerances, the verdict's RMS) are set for
// the first; NoiseScale tells how much wider the scans at hand need them.
//
// For every stride-th valid cell, the plane through the valid cells of its
// (2 half_window + 1)^2 lattice window (the cell itself left out, PCA)
// gives the cell's distance to its neighbourhood's surface. Per range bin,
// 1.4826 x the median of those distances (the median absolute deviation of
// a normal distribution) is the noise sigma there; depth steps and corners
// are a minority of the cells and do not move the median.
#ifndef EDGEFIT_SCAN_SCAN_NOISE_H_
#define EDGEFIT_SCAN_SCAN_NOISE_H_

#include <string>
#include <vector>

#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct ScanNoiseOptions {
  int stride = 5;        // every n-th valid cell is measured,
  int max_cells = 100000;  // and at most about this many per scan (a wider stride)
  int half_window = 3;   // [cells]
  int min_neighbours = 12;
  double bin = 0.5;      // range bin [m]
  int min_per_bin = 100; // fewer measurements: the bin takes its neighbours' sigma

  bool IsValid(std::string* error) const;
};

struct ScanNoise {
  double bin = 0.5;            // [m]
  std::vector<double> sigma;   // per bin [range k*bin, (k+1)*bin) [m]; NaN: no measurement
  size_t measured = 0;         // cells measured
  double median_sigma = 0.0;   // over every measured cell [m]

  bool empty() const { return measured == 0; }
  // Sigma at `range` [m]: the bin's, or the nearest bin's that has one; the
  // overall median without any.
  double At(double range) const;
};

// Deterministic for any thread count.
ScanNoise EstimateScanNoise(const ScanSet& scans, const ScanNoiseOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_SCAN_NOISE_H_
