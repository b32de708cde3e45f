// Internal: layout of the conveyance system (paper Fig. 4b, Sec. 3.2 and 6),
// shared by its link meshes and its URDF. base_link sits on the floor at the
// frame's centre, x along the 5.5 m length, z up. Two carriages slide along
// the rails (x), each lifts a beam (z); lifter_1 carries two fixed arms,
// lifter_2 two clamp arms sliding outwards (+y / -y). Every arm ends in a
// conical locating pin whose apex is the arm's highest point, the convex tip
// the base-link fitting (Sec. 6.1) finds in a height map; the tips are
// mirror-symmetric about the long axis when the clamps are equal.
#ifndef EDGEFIT_SRC_ASSETS_CONVEYOR_LAYOUT_H_
#define EDGEFIT_SRC_ASSETS_CONVEYOR_LAYOUT_H_

namespace edgefit {
namespace assets_internal {

struct ConveyorLayout {
  double length = 5.5;           // [m] longitudinal beams along x.
  double beam_y = 0.62;          // [m] beam and rail centre lines at y = +-beam_y.
  double rail_top = 0.905;       // [m] carriage joints' z (base_link).
  double leg_x[4] = {-2.5, -0.85, 0.85, 2.5};
  double carriage_x = 1.4;       // [m] carriage_1 at -x, carriage_2 at +x (joint origins).
  double carriage_travel = 0.85; // [m] +- along x.
  double lifter_z = 0.30;        // [m] lifter joint above the carriage frame.
  double lifter_travel = 0.20;   // [m] 0 .. travel up.
  double rod_y = 0.30;           // [m] lifter guide rods at y = +-rod_y.
  double fixed_arm_y = 0.45;     // [m] lifter_1 arms at y = +-fixed_arm_y.
  double clamp_y = 0.40;         // [m] clamp joints at y = +-clamp_y on lifter_2.
  double clamp_z = 0.13;         // [m] clamp joints above the lifter frame (beam top).
  double clamp_travel = 0.12;    // [m] 0 .. travel outwards.
  double tip_z = 0.475;          // [m] arm tips above the lifter frame.
};

inline const ConveyorLayout& ConveyorLayoutValues() {
  static const ConveyorLayout layout;
  return layout;
}

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_CONVEYOR_LAYOUT_H_
