// Internal: the spot-welding robot's kinematic layout, shared by its link
// meshes and its URDF so the two cannot disagree. A 200 kg-class six-axis
// robot (link frames at the joint axes, metres, radians; x forward, z up at
// the zero posture, where the upper arm is vertical and the forearm
// horizontal):
//
//   joint_1  z  base_link -> link_1  at (0, 0, 0.35)      pedestal top
//   joint_2  y  link_1 -> link_2     at (0.35, 0, 0.45)   offset shoulder
//   joint_3  y  link_2 -> link_3     at (0, 0, 1.10)      upper arm
//   joint_4  x  link_3 -> link_4     at (0.25, 0, 0.05)   forearm roll
//   joint_5  y  link_4 -> link_5     at (0.95, 0, 0)      wrist bend
//   joint_6  x  link_5 -> link_6     at (0.175, 0, 0)     flange roll
//   tool0       link_6, 0.04 beyond the flange root, z out of the flange
//
// Counter-balancer (closed loop, paper Sec. 3.1): a cylinder pivots about y
// on a bracket of link_1 at kBalancerPivot; its piston slides along the
// cylinder's x-axis and its eye must meet the crank pin of link_2 at
// kBalancerCrankPin, so balancer_cylinder_joint and balancer_piston_joint
// follow joint_2. Both points lie in the plane y = 0.42, outside the upper
// arm (y 0.08 .. 0.32).
#ifndef EDGEFIT_SRC_ASSETS_ROBOT_LAYOUT_H_
#define EDGEFIT_SRC_ASSETS_ROBOT_LAYOUT_H_

#include <Eigen/Core>

namespace edgefit {
namespace assets_internal {

struct RobotLayout {
  double j1_height = 0.35;                               // [m] base_link z of joint_1
  Eigen::Vector3d shoulder = {0.35, 0.0, 0.45};          // link_1: joint_2
  double upper_arm = 1.10;                               // link_2: joint_3 along z
  Eigen::Vector3d forearm_root = {0.25, 0.0, 0.05};      // link_3: joint_4
  double forearm = 0.95;                                 // link_4: joint_5 along x
  double wrist = 0.175;                                  // link_5: joint_6 along x
  double flange = 0.04;                                  // link_6: tool0 along x
  double arm_y_min = 0.08, arm_y_max = 0.32;             // upper arm side band [m]
  Eigen::Vector3d balancer_pivot = {-0.35, 0.42, 0.55};  // link_1
  Eigen::Vector3d crank_pin = {-0.22, 0.42, 0.06};       // link_2
  double cylinder_body_start = 0.06, cylinder_body_end = 0.46;  // balancer_cylinder x [m]
  double piston_rod_length = 0.40;                              // behind the piston eye [m]
};

inline const RobotLayout& Layout() {
  static const RobotLayout layout;
  return layout;
}

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_ROBOT_LAYOUT_H_
