// The laser beam's footprint and mixed pixels. A TLS beam is not a ray: it
// leaves the aperture with a diameter and spreads with a divergence, so at
// range t its 1/e^2 radius is
//
//   w(t) = exit_diameter / 2 + t * tan(divergence / 2).
//
// Where the footprint falls on surfaces at different depths (a silhouette
// against the background, a step between links), a phase-based scanner
// returns the energy-weighted mean of their ranges: a "mixed pixel" floating
// between the surfaces; a pulse scanner with echo separation returns one of
// them. The virtual scanner samples the footprint with `sub_rays` rays in a
// sunflower pattern over the 1/e^2 disc (ray j at radius w sqrt((j+0.5)/N)),
// each weighted by the Gaussian profile exp(-2 r^2 / w^2), the reflectance
// of what it hits, |cos incidence| and (t_centre / t)^2. Cells whose
// neighbourhood lies on one smooth surface keep the central ray (the mean
// over a plane is its centre); the others cast the sub-rays.
//
// A cell is labelled a mixed pixel (kMixedPixelFlag) when its sub-ray hits
// spread along the central hit's surface normal by more than mixed_depth: a
// plane seen at a grazing angle is one surface and is not a mixed pixel.
//
// Presets from published figures (Chaudhry, Salido-Monzu, Wieser, Remote
// Sens. 13(4):615, 2021, and the makers' data sheets): "faro_focus" 2.5 mm
// exit, 0.19 mrad; "leica_p40" 3.5 mm, 0.23 mrad; "zf_5016" 0.3 mrad
// half-angle (0.6 mrad full); its 0.4 mm exit is our estimate from the
// paper's 1 mm beam sigma at 6 m.
#ifndef EDGEFIT_SCANNER_BEAM_FOOTPRINT_H_
#define EDGEFIT_SCANNER_BEAM_FOOTPRINT_H_

#include <string>

#include "edgefit/core/status.h"

namespace edgefit {

enum class MixedReturn {
  kMean,       // energy-weighted mean range of every sub-ray (phase-based scanners)
  kStrongest,  // mean range of the depth layer holding the strongest sub-ray
};

struct BeamOptions {
  // 0: an ideal ray (one per cell, no footprint); the defaults below are a
  // FARO Focus class scanner once sub_rays > 1.
  int sub_rays = 1;
  double exit_diameter = 0.0025;  // [m] 1/e^2 diameter at the aperture
  double divergence = 0.00019;    // [rad] full angle
  MixedReturn mixed_return = MixedReturn::kMean;
  // [m] Sub-ray hits spread along the surface normal beyond this make a
  // mixed pixel (and decide which cells need sub-rays).
  double mixed_depth = 0.003;

  bool enabled() const { return sub_rays > 1; }
  // 1/e^2 radius of the footprint at range t [m].
  double Radius(double t) const;
  bool IsValid(std::string* error) const;
};

// "ideal" (one ray), "faro_focus", "leica_p40", "zf_5016" (16 sub-rays each).
Status BeamPreset(const std::string& name, BeamOptions* beam);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_BEAM_FOOTPRINT_H_
