// The fit's distance thresholds, scaled to the noise of the scans at hand.
//
// Every gate, tolerance and bar of FitOptions in metres was set on laser
// scans with about a millimetre of range noise (the paper's 5 mm final gate
// is 5 sigma of it). A stereo depth camera's points lie a centimetre off
// the surface at 2 m, and the error is correlated over many pixels (the
// matcher smooths it), so a local plane fit does not see it: on the ZED 2i
// frames it finds 0.8 mm, while the frame lies 11 mm from the robot's CAD
// at its reference pose (median). The noise that matters is measured where
// the fit meets the model: the base body is registered from its best rough
// pose with a wide, fixed gate, and sigma = 1.4826 x the median distance of
// its matched samples to their scan points (robust to clutter and parts the
// CAD lacks). Every distance threshold is then multiplied by
//   k = clamp(sigma / reference_sigma, 1, max_scale)
// (the occlusion tolerances and final gates to at least 3 sigma), and
// coverings are not sought (a jacket's millimetres are inside the noise):
// laser scans keep the thresholds they were measured with (k = 1), a depth
// camera's are widened in proportion; loss margins per sample (the sweeps'
// Eq. (9) saturates at tau_dist) scale with them.
#ifndef EDGEFIT_PIPELINE_NOISE_SCALE_H_
#define EDGEFIT_PIPELINE_NOISE_SCALE_H_

#include <string>

#include "edgefit/pipeline/fit_options.h"

namespace edgefit {

// k for a measured sigma [m] (the header), with NoiseOptions' bounds.
double NoiseScaleFor(double sigma, const NoiseOptions& options);

// `options` for scans whose noise is sigma [m]: with k = NoiseScaleFor
// every distance threshold (gates, tolerances, the verdict's RMS, loss
// margins) multiplied by k, the occlusion tolerances and final gates to at
// least 3 sigma, no coverings, the covariance's patch deviation at least
// sigma (the sensor's error is correlated); angles, counts and shares
// unchanged. k = 1 (laser scans) returns `options` as they are.
FitOptions ScaledToNoise(const FitOptions& options, double sigma);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_NOISE_SCALE_H_
