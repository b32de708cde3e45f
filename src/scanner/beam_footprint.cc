#include "edgefit/scanner/beam_footprint.h"

#include <cmath>

namespace edgefit {

double BeamOptions::Radius(double t) const {
  return 0.5 * exit_diameter + t * std::tan(0.5 * divergence);
}

bool BeamOptions::IsValid(std::string* error) const {
  if (sub_rays < 1 || sub_rays > 256) {
    *error = "beam: sub_rays must be 1..256";
  } else if (!(exit_diameter >= 0.0 && exit_diameter < 0.05)) {
    *error = "beam: exit_diameter must be in [0, 50 mm)";
  } else if (!(divergence >= 0.0 && divergence < 0.01)) {
    *error = "beam: divergence must be in [0, 10 mrad)";
  } else if (!(mixed_depth > 0.0)) {
    *error = "beam: mixed_depth must be positive";
  } else {
    return true;
  }
  return false;
}

Status BeamPreset(const std::string& name, BeamOptions* beam) {
  BeamOptions b;
  b.sub_rays = 16;
  if (name == "ideal") {
    b.sub_rays = 1;
  } else if (name == "faro_focus") {
    b.exit_diameter = 0.0025;
    b.divergence = 0.00019;
  } else if (name == "leica_p40") {
    b.exit_diameter = 0.0035;
    b.divergence = 0.00023;
  } else if (name == "zf_5016") {
    b.exit_diameter = 0.0004;
    b.divergence = 0.0006;
  } else {
    return Status::Error("unknown beam '" + name + "' (ideal, faro_focus, leica_p40, zf_5016)");
  }
  *beam = b;
  return Status::Ok();
}

}  // namespace edgefit
