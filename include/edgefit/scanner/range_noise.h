// Range noise and dropouts as a function of the return's strength. The
// range precision of a TLS falls with the received signal, which falls with
// the incidence angle theta and the surface's reflectance rho (Soudarissanane
// et al., "Incidence angle influence on the quality of terrestrial laser
// scanning points", ISPRS Laser Scanning 2009; Wujanz et al., "An
// intensity-based stochastic model for terrestrial laser scanners", Sensors
// 18(7):2187, 2018, model sigma as a power of the intensity). The exponent
// -1/2 below is our choice, not fitted to a scanner. With the relative
// signal
//
//   S = (rho / reference_reflectance) * |cos theta|
//
// (for a footprint on several surfaces: the energy-weighted mean over its
// sub-rays), the range noise is
//
//   sigma = noise_sigma * min(max_factor, S^-1/2),
//
// and the return drops out with probability 1 below dropout_signal_none,
// 0 above dropout_signal_full, linear between: grazing incidence and dark
// surfaces (black cable harnesses) lose points.
#ifndef EDGEFIT_SCANNER_RANGE_NOISE_H_
#define EDGEFIT_SCANNER_RANGE_NOISE_H_

#include <string>

namespace edgefit {

struct RangeNoiseOptions {
  // false: sigma = noise_sigma everywhere and no dropouts (the ideal scanner).
  bool signal_model = false;
  double reference_reflectance = 0.5;  // surface whose perpendicular return has noise_sigma
  double max_factor = 4.0;             // cap on sigma / noise_sigma
  double dropout_signal_none = 0.04;   // S below this: no return
  double dropout_signal_full = 0.12;   // S above this: always a return

  // sigma / noise_sigma at relative signal S.
  double NoiseFactor(double signal) const;
  // Probability that a return of relative signal S is lost.
  double DropoutProbability(double signal) const;
  bool IsValid(std::string* error) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_RANGE_NOISE_H_
