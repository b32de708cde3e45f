// Random joint values for the virtual benchmark postures (paper Sec. 7.3:
// "three unique postures"), reproducible from a seed.
#ifndef EDGEFIT_SCANNER_RANDOM_JOINTS_H_
#define EDGEFIT_SCANNER_RANDOM_JOINTS_H_

#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// A full joint vector (indexed like model.joints()): every independent joint
// uniform inside its limits [lower, upper] (continuous joints, and revolute
// joints without limits: [-pi, pi]); fixed joints 0; mimic and loop-closure
// joints resolved by ResolveDependentJoints. When a loop closure cannot be
// met for a draw, the independent joints are redrawn (the next draws of the
// same seeded stream) up to 64 times; after that the last draw is returned
// with its best-effort dependent values. Uses its own SplitMix64 stream, so
// the result is the same on every platform and standard library.
std::vector<double> RandomJointValues(const KinematicModel& model, uint64_t seed);

// A random posture that a real scan could show: like RandomJointValues, but
// redrawn (deterministically, from the same seed) until no link mesh posed on
// T_world_base reaches below the floor z = floor_z - tolerance [m]. Self
// collisions are not checked. Returns false, with the last draw in *q, when
// `max_draws` draws all touch the floor.
bool RandomJointValuesAboveFloor(const KinematicModel& model, const Pose& T_world_base,
                                 double floor_z, uint64_t seed, std::vector<double>* q,
                                 double tolerance = 0.002, int max_draws = 256);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_RANDOM_JOINTS_H_
