// Link geometry of the servo spot-welding gun (weld_gun_layout.h): adapter
// plate with bolt holes, gun body, welding transformer with cooling fins,
// servo motor with belt cover, a C-shaped fixed arm and the electrodes.
#include <cmath>

#include "edgefit/assets/motor_housing.h"
#include "edgefit/assets/perforated_plate.h"
#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/assets/revolved_mesh.h"
#include "robot_link_meshes.h"
#include "weld_gun_layout.h"

namespace edgefit {
namespace assets_internal {
namespace {

constexpr int kSegments = 64;

TriangleMesh GunBase() {
  const WeldGunLayout& G = GunLayout();
  TriangleMesh m;
  PerforatedPlateOptions plate;
  plate.size = {0.22, 0.22};
  plate.thickness = 0.025;
  for (double x : {-0.075, 0.075}) {
    for (double y : {-0.075, 0.075}) plate.holes.push_back({{x, y}, 0.011});
  }
  plate.hole_segments = 24;
  m.Append(MakePerforatedPlate(plate), At(0, 0, 0.0125));
  m.Append(MakeChamferedBox({0.16, 0.16, 0.06}, 0.008), At(0, 0, 0.05));   // insulator
  m.Append(MakeChamferedBox({0.26, 0.20, 0.32}, 0.015), At(0, 0, 0.235));  // body
  m.Append(ChamferedCylinder(0.045, G.electrode_joint_z - 0.385, 0.005, kSegments),
           At(0, 0, 0.385));  // electrode guide sleeve
  // Welding transformer on -x with vertical cooling fins and two terminals.
  m.Append(MakeChamferedBox({0.22, 0.24, 0.30}, 0.012), At(-0.235, 0, 0.24));
  for (int k = -3; k <= 3; ++k) {
    m.Append(MakeChamferedBox({0.03, 0.008, 0.26}, 0.0015), At(-0.358, 0.03 * k, 0.24));
  }
  for (double y : {-0.06, 0.06}) {
    m.Append(ChamferedCylinder(0.02, 0.05, 0.003, 24), At(-0.24, y, 0.385));
  }
  // Servo motor on +y, driving the electrode through a belt under the cover.
  MotorHousingOptions motor;
  motor.radius = 0.06;
  motor.length = 0.24;
  motor.flange_radius = 0.078;
  motor.flange_thickness = 0.012;
  motor.chamfer = 0.005;
  motor.rib_height = 0.009;
  motor.rib_width = 0.006;
  motor.segments = kSegments;
  m.Append(MakeMotorHousing(motor), AlongMinusZ(0, 0.17, 0.37));
  m.Append(MakeChamferedBox({0.12, 0.30, 0.06}, 0.008), At(0, 0.08, 0.40));  // belt cover
  return m;
}

TriangleMesh GunFixedArm() {
  const WeldGunLayout& G = GunLayout();
  TriangleMesh m;
  m.Append(MakeChamferedBox({0.14, 0.10, 0.08}, 0.008), At(0.17, 0, 0.37));  // clamp block
  m.Append(MakeTaperedCasting({0.12, 0.07}, {0.08, 0.06}, {0, 0}, 0.60, 0.012, 0.006),
           At(0.18, 0, 0.36));
  m.Append(MakeChamferedBox({0.26, 0.06, 0.08}, 0.008), At(0.08, 0, G.fixed_tip_z + 0.12));
  // Fixed electrode: holder, shank, domed cap ending in the tip at tcp.
  const double top = G.fixed_tip_z + 0.085;
  m.Append(MakeRevolvedSolid({{0.0, 0.022}, {0.05, 0.022}, {0.05, 0.016}, {0.07, 0.016},
                              {0.085, 0.007}},
                             kSegments),
           AlongMinusZ(0, 0, top));
  return m;
}

TriangleMesh GunElectrode() {
  const WeldGunLayout& G = GunLayout();
  return MakeRevolvedSolid({{-0.12, 0.025}, {G.moving_tip - 0.065, 0.025},
                            {G.moving_tip - 0.065, 0.016}, {G.moving_tip - 0.015, 0.016},
                            {G.moving_tip, 0.007}},
                           kSegments);
}

}  // namespace

std::vector<LinkMesh> WeldGunLinkMeshes() {
  return {{"gun_base", GunBase()}, {"gun_fixed_arm", GunFixedArm()},
          {"gun_electrode", GunElectrode()}};
}

}  // namespace assets_internal
}  // namespace edgefit
