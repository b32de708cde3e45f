// Internal: layout of the servo spot-welding gun (end effector, paper
// Sec. 3.1 keeps it in its own URDF). Frames: gun_base is the robot's tool0
// (z out of the flange); the gun is ~1 m long along +z. The moving
// electrode slides along +z on gun_joint from the body towards the fixed
// electrode held by the C-arm; tcp is at the fixed electrode's tip, its z
// pointing back at the moving electrode.
#ifndef EDGEFIT_SRC_ASSETS_WELD_GUN_LAYOUT_H_
#define EDGEFIT_SRC_ASSETS_WELD_GUN_LAYOUT_H_

namespace edgefit {
namespace assets_internal {

struct WeldGunLayout {
  double electrode_joint_z = 0.465;  // [m] gun_joint origin (top of the guide sleeve).
  double moving_tip = 0.265;         // [m] moving tip above gun_joint's frame.
  double fixed_tip_z = 0.83;         // [m] tcp: fixed electrode tip on the axis.
  double stroke = 0.10;              // [m] gun_joint upper limit: tips touch.
};

inline const WeldGunLayout& GunLayout() {
  static const WeldGunLayout layout;
  return layout;
}

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_WELD_GUN_LAYOUT_H_
