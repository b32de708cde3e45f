// Link geometry of the conveyance system: welded steel frame (chamfered
// beams, legs, feet plates with anchor holes), carriages with guide blocks,
// a perforated deck, guide tubes and a lift drive, lifter beams with arms
// ending in conical locating pins.
#include "conveyor_link_meshes.h"

#include "conveyor_layout.h"
#include "edgefit/assets/motor_housing.h"
#include "edgefit/assets/perforated_plate.h"
#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/assets/revolved_mesh.h"
#include "robot_link_meshes.h"

namespace edgefit {
namespace assets_internal {
namespace {

constexpr int kPinSegments = 48;

// An arm from z = 0 up to the pin apex at `tip_height` [m]: tapered post,
// then a cone whose apex is the arm's single highest point.
TriangleMesh Arm(double tip_height) {
  constexpr double kPin = 0.085;  // [m] pin height above the post.
  TriangleMesh m;
  m.Append(MakeTaperedCasting({0.10, 0.10}, {0.06, 0.06}, {0, 0}, tip_height - kPin + 0.005, 0.012,
                              0.006));
  m.Append(MakeRevolvedSolid({{0.0, 0.02}, {0.045, 0.02}, {0.07, 0.012}, {kPin, 0.0}}, kPinSegments),
           At(0, 0, tip_height - kPin));
  return m;
}

TriangleMesh ConveyorBaseLink() {
  const ConveyorLayout& L = ConveyorLayoutValues();
  TriangleMesh m;
  for (double side : {-1.0, 1.0}) {
    const double y = side * L.beam_y;
    m.Append(MakeChamferedBox({L.length, 0.16, 0.24}, 0.01), At(0, y, L.rail_top - 0.165));
    m.Append(MakeChamferedBox({L.length - 0.1, 0.06, 0.05}, 0.005), At(0, y, L.rail_top - 0.025));
    for (double x_end : {-0.5 * L.length, 0.5 * L.length}) {  // end stops
      m.Append(MakeChamferedBox({0.04, 0.12, 0.10}, 0.006),
               At(x_end - (x_end > 0 ? 0.03 : -0.03), y, L.rail_top + 0.04));
    }
    for (double x : L.leg_x) {
      m.Append(MakeChamferedBox({0.14, 0.14, 0.61}, 0.01), At(x, y, 0.325));
      PerforatedPlateOptions foot;
      foot.size = {0.30, 0.36};
      foot.thickness = 0.025;
      for (double hx : {-0.10, 0.10}) {
        for (double hy : {-0.13, 0.13}) foot.holes.push_back({{hx, hy}, 0.011});
      }
      foot.hole_segments = 24;
      m.Append(MakePerforatedPlate(foot), At(x, y, 0.0125));
    }
  }
  for (double x : L.leg_x) {  // low cross beams between the leg pairs
    m.Append(MakeChamferedBox({0.10, 2.0 * L.beam_y - 0.12, 0.10}, 0.008), At(x, 0, 0.30));
  }
  for (double x : {-2.5, 0.0, 2.5}) {  // top cross beams under the rails
    m.Append(MakeChamferedBox({0.12, 2.0 * L.beam_y - 0.12, 0.12}, 0.008), At(x, 0, 0.72));
  }
  m.Append(MakeChamferedBox({4.8, 0.20, 0.06}, 0.006), At(0, 0, 0.375));  // cable tray
  // Drive unit at the +x end: gearbox under the top cross beam, motor on +y.
  m.Append(MakeChamferedBox({0.25, 0.30, 0.22}, 0.015), At(2.4, 0, 0.56));
  MotorHousingOptions motor;
  motor.radius = 0.07;
  motor.length = 0.25;
  motor.flange_radius = 0.09;
  m.Append(MakeMotorHousing(motor), AlongY(2.4, 0.145, 0.56));
  return m;
}

TriangleMesh Carriage() {
  const ConveyorLayout& L = ConveyorLayoutValues();
  TriangleMesh m;
  for (double x : {-0.28, 0.28}) {
    for (double y : {-L.beam_y, L.beam_y}) {
      m.Append(MakeChamferedBox({0.16, 0.10, 0.075}, 0.008), At(x, y, 0.0375));  // guide blocks
    }
  }
  PerforatedPlateOptions deck;
  deck.size = {0.8, 1.4};
  deck.thickness = 0.05;
  for (double x : {-0.25, 0.0, 0.25}) {
    for (double y : {-L.rod_y, L.rod_y}) deck.holes.push_back({{x, y}, 0.035});
  }
  m.Append(MakePerforatedPlate(deck), At(0, 0, 0.095));
  for (double y : {-L.rod_y, L.rod_y}) {  // lifter guide tubes around the rod holes
    m.Append(MakeTube(0.035, 0.05, L.lifter_z - 0.115, 0.004, 64), At(0, y, 0.115));
  }
  m.Append(MakeChamferedBox({0.18, 0.22, 0.16}, 0.012), At(0, 0, 0.195));  // lift gearbox
  MotorHousingOptions motor;
  motor.radius = 0.06;
  motor.length = 0.2;
  motor.flange_radius = 0.075;
  m.Append(MakeMotorHousing(motor), AlongX(0.085, 0, 0.2));
  return m;
}

TriangleMesh Lifter(bool with_fixed_arms) {
  const ConveyorLayout& L = ConveyorLayoutValues();
  TriangleMesh m;
  for (double y : {-L.rod_y, L.rod_y}) {
    m.Append(ChamferedCylinder(0.03, L.lifter_z + 0.05, 0.003, 64), At(0, y, -L.lifter_z));
  }
  m.Append(MakeChamferedBox({0.24, 1.2, 0.08}, 0.01), At(0, 0, L.clamp_z - 0.04));
  if (with_fixed_arms) {
    for (double y : {-L.fixed_arm_y, L.fixed_arm_y}) {
      m.Append(Arm(L.tip_z - L.clamp_z + 0.005), At(0, y, L.clamp_z - 0.005));
    }
  } else {
    for (double y : {-L.clamp_y, L.clamp_y}) {  // clamp guide rails
      m.Append(MakeChamferedBox({0.05, 0.26, 0.02}, 0.004),
               At(0, y + (y > 0 ? 0.08 : -0.08), L.clamp_z + 0.005));
    }
  }
  return m;
}

// Frame at the clamp joint on the lifter beam's top face.
TriangleMesh Clamp() {
  const ConveyorLayout& L = ConveyorLayoutValues();
  TriangleMesh m;
  m.Append(MakeChamferedBox({0.14, 0.12, 0.06}, 0.008), At(0, 0, 0.045));  // slide block
  m.Append(Arm(L.tip_z - L.clamp_z - 0.07), At(0, 0, 0.07));
  return m;
}

}  // namespace

std::vector<LinkMesh> ConveyorLinkMeshes() {
  return {{"base_link", ConveyorBaseLink()}, {"carriage_1", Carriage()},
          {"lifter_1", Lifter(true)},        {"carriage_2", Carriage()},
          {"lifter_2", Lifter(false)},       {"clamp_2_left", Clamp()},
          {"clamp_2_right", Clamp()}};
}

}  // namespace assets_internal
}  // namespace edgefit
