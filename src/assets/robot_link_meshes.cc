// Link geometry of the spot-welding robot: castings as chamfered tapered
// lofts, joint bosses and motors as revolved solids, a floor plate with
// anchor-bolt holes. Parts of a link overlap where they join (no CSG): each
// part is closed, so the link mesh is closed too.
#include "robot_link_meshes.h"

#include <cmath>

#include "edgefit/assets/motor_housing.h"
#include "edgefit/assets/perforated_plate.h"
#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/assets/revolved_mesh.h"
#include "robot_layout.h"

namespace edgefit {
namespace assets_internal {
namespace {

constexpr int kLargeSegments = 128;  // Bosses of ~0.2 m radius: 2.8 deg facets, 9 mm chords.
constexpr int kSmallSegments = 64;  // Pins, eyes and small motors.

Pose Yawed(double angle, const Pose& T) {
  return Pose(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())) * T;
}

MotorHousingOptions Motor(double radius, double length) {
  MotorHousingOptions o;
  o.radius = radius;
  o.length = length;
  o.flange_radius = 1.3 * radius;
  o.flange_thickness = 0.2 * radius;
  o.chamfer = 0.08 * radius;
  o.rib_height = 0.15 * radius;
  o.rib_width = 0.1 * radius;
  o.segments = radius > 0.06 ? 96 : kSmallSegments;
  return o;
}

TriangleMesh BaseLink() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  PerforatedPlateOptions plate;
  plate.size = {1.0, 1.0};
  plate.thickness = 0.04;
  for (double x : {-0.42, 0.0, 0.42}) {
    for (double y : {-0.42, 0.0, 0.42}) {
      if (x != 0.0 || y != 0.0) plate.holes.push_back({{x, y}, 0.022});  // M20 anchors
    }
  }
  m.Append(MakePerforatedPlate(plate), At(0, 0, 0.02));
  // Pedestal: bottom flange, slightly tapered column, top flange under link_1.
  const double top = L.j1_height - 0.005;
  m.Append(MakeRevolvedSolid({{0.035, 0.36}, {0.075, 0.36}, {0.085, 0.35}, {0.085, 0.28},
                              {top - 0.05, 0.26}, {top - 0.05, 0.31}, {top - 0.005, 0.31},
                              {top, 0.305}},
                             kLargeSegments));
  for (int k = 0; k < 8; ++k) {
    const double angle = (k + 0.5) * M_PI / 4.0;
    // Gussets: 80 mm at the flange tapering to 12 mm, 200 mm high.
    m.Append(MakeTaperedCasting({0.08, 0.024}, {0.012, 0.024}, {-0.034, 0.0}, 0.2, 0.004, 0.0),
             Yawed(angle, At(0.305, 0, 0.083)));
    m.Append(HexBoltHead(0.016, 0.014), Yawed(k * M_PI / 4.0, At(0.32, 0, 0.083)));
  }
  m.Append(MakeChamferedBox({0.14, 0.26, 0.16}, 0.012), At(-0.33, 0, 0.19));  // junction box
  for (double y : {-0.06, 0.06}) {
    m.Append(MakeRevolvedSolid({{0, 0.03}, {0.05, 0.03}, {0.05, 0.022}, {0.075, 0.022}},
                               kSmallSegments),
             AlongMinusX(-0.395, y, 0.19));
  }
  return m;
}

TriangleMesh Link1() {
  const RobotLayout& L = Layout();
  const Eigen::Vector3d& J = L.shoulder;
  const Eigen::Vector3d& C = L.balancer_pivot;
  TriangleMesh m;
  m.Append(MakeRevolvedSolid({{0.0, 0.315}, {0.01, 0.33}, {0.05, 0.33}, {0.06, 0.315}},
                             kLargeSegments));  // turntable
  m.Append(MakeTaperedCasting({0.80, 0.76}, {0.70, 0.72}, {0.05, 0.0}, 0.15, 0.08, 0.012),
           At(0, 0, 0.05));
  // Shoulder column on the -y side; the upper arm runs beside it on +y.
  m.Append(MakeTaperedCasting({0.55, 0.36}, {0.36, 0.36}, {0.08, 0.0}, J.z() - 0.19, 0.04, 0.0),
           At(J.x() - 0.08, -0.12, 0.19));
  m.Append(MakeRevolvedSolid({{0, 0.17}, {0.012, 0.19}, {0.348, 0.19}, {0.36, 0.17}},
                             kLargeSegments),
           AlongMinusY(J.x(), 0.06, J.z()));
  m.Append(MakeMotorHousing(Motor(0.085, 0.26)), AlongMinusY(J.x(), -0.30, J.z()));  // joint_2
  m.Append(MakeMotorHousing(Motor(0.075, 0.22)), At(-0.18, -0.2, 0.198));         // joint_1
  // Balancer bracket and pivot pin.
  m.Append(MakeChamferedBox({0.12, 0.06, C.z() - 0.13}, 0.01),
           At(C.x(), C.y() - 0.09, 0.5 * (C.z() + 0.18) + 0.025));
  m.Append(ChamferedCylinder(0.03, 0.2, 0.004, kSmallSegments), AlongY(C.x(), C.y() - 0.12, C.z()));
  return m;
}

TriangleMesh Link2() {
  const RobotLayout& L = Layout();
  const double y0 = L.arm_y_min, y1 = L.arm_y_max, yc = 0.5 * (y0 + y1);
  const Eigen::Vector3d& P = L.crank_pin;
  TriangleMesh m;
  m.Append(MakeRevolvedSolid({{0, 0.17}, {0.012, 0.19}, {y1 - y0 - 0.012, 0.19}, {y1 - y0, 0.17}},
                             kLargeSegments),
           AlongY(0, y0, 0));
  m.Append(MakeTaperedCasting({0.34, 0.22}, {0.24, 0.20}, {0, 0}, L.upper_arm, 0.035, 0.0),
           At(0, yc, 0));
  m.Append(MakeChamferedBox({0.16, 0.025, 0.65}, 0.006), At(0, y1 - 0.005, 0.55));  // cover
  m.Append(MakeRevolvedSolid({{0, 0.14}, {0.01, 0.15}, {y1 - y0 - 0.02, 0.15}, {y1 - y0 - 0.01, 0.14}},
                             kLargeSegments),
           AlongY(0, y0, L.upper_arm));
  m.Append(MakeMotorHousing(Motor(0.075, 0.22)), AlongY(0, y1 - 0.01, L.upper_arm));  // joint_3
  // Balancer crank from the hub to the pin, in the plane y = y1 + 0.02.
  const double phi = std::atan2(P.z(), P.x());
  Pose T_crank = At(0.5 * P.x(), y1 + 0.02, 0.5 * P.z());
  T_crank.rotate(Eigen::AngleAxisd(-phi, Eigen::Vector3d::UnitY()));
  m.Append(MakeChamferedBox({std::hypot(P.x(), P.z()) + 0.1, 0.04, 0.1}, 0.008), T_crank);
  m.Append(ChamferedCylinder(0.028, 0.15, 0.004, kSmallSegments), AlongY(P.x(), y1, P.z()));
  return m;
}

TriangleMesh Link3() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(ChamferedCylinder(0.15, 0.26, 0.012, kLargeSegments), AlongY(0, -0.19, 0));
  m.Append(MakeChamferedBox({0.46, 0.26, 0.30}, 0.025), At(0.0, -0.06, 0.06));
  m.Append(MakeRevolvedSolid({{0, 0.15}, {0.01, 0.16}, {0.04, 0.16}, {0.05, 0.15}}, kLargeSegments),
           AlongX(L.forearm_root.x() - 0.05, 0, L.forearm_root.z()));
  for (const Eigen::Vector2d& yz : {Eigen::Vector2d(-0.13, 0.13), Eigen::Vector2d(0.01, 0.13),
                                    Eigen::Vector2d(-0.06, -0.02)}) {
    m.Append(MakeMotorHousing(Motor(0.05, 0.18)), AlongMinusX(-0.225, yz.x(), yz.y()));  // wrist
  }
  return m;
}

TriangleMesh Link4() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(MakeRevolvedSolid({{0, 0.14}, {0.01, 0.15}, {0.10, 0.15}, {0.10, 0.135}, {0.62, 0.11},
                              {0.64, 0.10}},
                             kLargeSegments),
           AlongX(0, 0, 0));
  for (double side : {-1.0, 1.0}) {
    m.Append(MakeChamferedBox({0.42, 0.04, 0.18}, 0.008), At(L.forearm - 0.17, side * 0.115, 0));
    const Pose T_hub = side > 0 ? AlongY(L.forearm, 0.095, 0) : AlongMinusY(L.forearm, -0.095, 0);
    m.Append(ChamferedCylinder(0.09, 0.05, 0.006, kLargeSegments), T_hub);
  }
  m.Append(MakeChamferedBox({0.30, 0.10, 0.05}, 0.008), At(0.35, 0, 0.135));  // drive cover
  return m;
}

TriangleMesh Link5() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(ChamferedCylinder(0.08, 0.18, 0.008, kLargeSegments), AlongY(0, -0.09, 0));
  m.Append(MakeRevolvedSolid({{0, 0.075}, {0.12, 0.075}, {0.12, 0.065}, {L.wrist - 0.01, 0.06},
                              {L.wrist - 0.005, 0.055}},
                             kLargeSegments),
           AlongX(0, 0, 0));
  return m;
}

TriangleMesh Link6() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(MakeRevolvedSolid({{-0.004, 0.05}, {0.02, 0.05}, {0.02, 0.08}, {L.flange - 0.004, 0.08},
                              {L.flange, 0.076}},
                             kLargeSegments),
           AlongX(0, 0, 0));
  for (int k = 0; k < 6; ++k) {  // Socket screws on the flange's back face.
    const double a = k * M_PI / 3.0;
    m.Append(ChamferedCylinder(0.007, 0.008, 0.001, 16),
             AlongMinusX(0.0205, 0.066 * std::cos(a), 0.066 * std::sin(a)));
  }
  return m;
}

// Cylinder frame at the pivot, body along +x.
TriangleMesh BalancerCylinder() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(ChamferedCylinder(0.05, 0.08, 0.006, kSmallSegments), AlongY(0, -0.04, 0));  // eye
  m.Append(MakeRevolvedSolid({{0.0, 0.045}, {0.02, 0.065}, {0.03, 0.075},
                              {L.cylinder_body_end - L.cylinder_body_start - 0.01, 0.075},
                              {L.cylinder_body_end - L.cylinder_body_start, 0.065},
                              {L.cylinder_body_end - L.cylinder_body_start, 0.04},
                              {L.cylinder_body_end - L.cylinder_body_start + 0.015, 0.04}},
                             kLargeSegments),
           AlongX(L.cylinder_body_start - 0.02, 0, 0));
  return m;
}

// Piston frame at its eye (the loop-closure point), rod along -x.
TriangleMesh BalancerPiston() {
  const RobotLayout& L = Layout();
  TriangleMesh m;
  m.Append(ChamferedCylinder(0.045, 0.08, 0.005, kSmallSegments), AlongY(0, -0.04, 0));  // eye
  m.Append(ChamferedCylinder(0.03, L.piston_rod_length, 0.003, kSmallSegments),
           AlongMinusX(-0.03, 0, 0));
  return m;
}

}  // namespace

TriangleMesh ChamferedCylinder(double radius, double length, double chamfer, int segments) {
  return MakeRevolvedSolid({{0.0, radius - chamfer}, {chamfer, radius}, {length - chamfer, radius},
                            {length, radius - chamfer}},
                           segments);
}

TriangleMesh HexBoltHead(double across_corners_radius, double height) {
  const double r = across_corners_radius, c = 0.15 * height;
  return MakeRevolvedSolid({{0.0, r}, {height - c, r}, {height, r - c}}, 6, M_PI / 6.0);
}

std::vector<LinkMesh> RobotLinkMeshes() {
  return {{"base_link", BaseLink()}, {"link_1", Link1()},
          {"link_2", Link2()},       {"link_3", Link3()},
          {"link_4", Link4()},       {"link_5", Link5()},
          {"link_6", Link6()},       {"balancer_cylinder", BalancerCylinder()},
          {"balancer_piston", BalancerPiston()}};
}

}  // namespace assets_internal
}  // namespace edgefit
