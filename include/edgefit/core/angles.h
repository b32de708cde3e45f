// Angle constants: pi and one degree in radians.
#ifndef EDGEFIT_CORE_ANGLES_H_
#define EDGEFIT_CORE_ANGLES_H_

namespace edgefit {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDeg = kPi / 180.0;  // one degree [rad]

}  // namespace edgefit

#endif  // EDGEFIT_CORE_ANGLES_H_
