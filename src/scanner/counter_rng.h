// Counter-based random numbers for the virtual scanner (internal).
//
// Every random draw is a pure function of (seed, stream, counter), so results
// do not depend on the thread that computes them or on the order of the
// work: the scan of a cell depends on (seed, scan, cell) only. SplitMix64
// (Steele et al., "Fast splittable pseudorandom number generators", 2014) is
// used as the mixing function; its output passes BigCrush as a hash of a
// counter.
#ifndef EDGEFIT_SRC_SCANNER_COUNTER_RNG_H_
#define EDGEFIT_SRC_SCANNER_COUNTER_RNG_H_

#include <cmath>
#include <cstdint>

#include "edgefit/core/angles.h"
#include "edgefit/core/split_mix64.h"

namespace edgefit {
namespace scanner_internal {

// Hash of (seed, stream, counter): distinct inputs give independent-looking outputs.
inline uint64_t CounterHash(uint64_t seed, uint64_t stream, uint64_t counter) {
  constexpr uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
  return Mix64(Mix64(Mix64(seed + kGolden) ^ (stream + 2 * kGolden)) ^ (counter + 3 * kGolden));
}

// Uniform in (0, 1) from the top 53 bits; never exactly 0 (safe for log).
inline double UnitOpen(uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

// A standard normal draw from two hashes (Box-Muller, cosine branch).
inline double StandardNormal(uint64_t bits_a, uint64_t bits_b) {
  return std::sqrt(-2.0 * std::log(UnitOpen(bits_a))) * std::cos(kTwoPi * UnitOpen(bits_b));
}

}  // namespace scanner_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_SCANNER_COUNTER_RNG_H_
