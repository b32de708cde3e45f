// Private: the seeded generator of the scene layer. SplitMix64 (Steele, Lea,
// Flood 2014) is fully specified, so a seed gives the same scene on every
// platform; std distributions are avoided because their output differs
// between standard libraries.
#ifndef EDGEFIT_SRC_SCENE_SCENE_RANDOM_H_
#define EDGEFIT_SRC_SCENE_SCENE_RANDOM_H_

#include <cstdint>

namespace edgefit {
namespace scene_internal {

class SceneRandom {
 public:
  explicit SceneRandom(uint64_t seed) : state_(seed) {}
  // A generator for sub-stream `index` of `seed`, independent of how many
  // draws other sub-streams made.
  static SceneRandom Stream(uint64_t seed, uint64_t index) {
    SceneRandom mix(seed ^ (index * 0xD1B54A32D192ED03ULL));
    return SceneRandom(mix.Next());
  }

  uint64_t Next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1) from the top 53 bits.
  double Uniform() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform integer in [lo, hi] (hi >= lo); the modulo bias is negligible
  // for the small ranges used here.
  int Int(int lo, int hi) { return lo + static_cast<int>(Next() % static_cast<uint64_t>(hi - lo + 1)); }

 private:
  uint64_t state_;
};

}  // namespace scene_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_SCENE_SCENE_RANDOM_H_
