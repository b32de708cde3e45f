// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
// generators", 2014): the one seeded generator of edgefit. It is tiny, passes
// BigCrush, and is fully specified, so a seed gives the same output on every
// platform and standard library (std distributions do not).
#ifndef EDGEFIT_CORE_SPLIT_MIX64_H_
#define EDGEFIT_CORE_SPLIT_MIX64_H_

#include <cstdint>

namespace edgefit {

// The SplitMix64 finaliser: a bijective 64-bit mix.
inline uint64_t Mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}

  // The seed of sub-stream `index` of `seed`: streams are independent of how
  // many draws the others made (one per link, per accessory, per stage, ...).
  static uint64_t StreamSeed(uint64_t seed, uint64_t index) {
    return SplitMix64(seed ^ (index * 0xd1b54a32d192ed03ULL)).Next();
  }
  static SplitMix64 Stream(uint64_t seed, uint64_t index) {
    return SplitMix64(StreamSeed(seed, index));
  }

  uint64_t Next() { return Mix64(state_ += 0x9e3779b97f4a7c15ULL); }
  // Uniform in [0, 1) from the top 53 bits.
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform integer in [lo, hi] (hi >= lo); the modulo bias is negligible for
  // the small ranges edgefit draws from.
  int Int(int lo, int hi) {
    return lo + static_cast<int>(Next() % static_cast<uint64_t>(hi - lo + 1));
  }

 private:
  uint64_t state_;
};

}  // namespace edgefit

#endif  // EDGEFIT_CORE_SPLIT_MIX64_H_
