// Servo motor housings as seen on robot joints and drives: a cylindrical
// body with a mounting flange at z = 0, a chamfered rear end with a raised
// encoder cap, axial cooling ribs and a connector box on top (+x side).
#ifndef EDGEFIT_ASSETS_MOTOR_HOUSING_H_
#define EDGEFIT_ASSETS_MOTOR_HOUSING_H_

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct MotorHousingOptions {
  double radius = 0.08;            // [m] body radius.
  double length = 0.25;            // [m] flange face (z = 0) to the rear face, along +z.
  double flange_radius = 0.1;      // [m] (> radius).
  double flange_thickness = 0.02;  // [m]
  double chamfer = 0.008;          // [m] flange and rear rims.
  double cap_radius_ratio = 0.6;   // encoder cap radius / body radius.
  double cap_height = 0.03;        // [m] beyond the rear face.
  int rib_count = 8;               // axial cooling ribs (0 for none).
  double rib_height = 0.012;       // [m] radial, outside the body.
  double rib_width = 0.008;        // [m]
  bool connector = true;           // connector box on the +x side.
  int segments = 64;               // around; facet angle 5.6 deg.
};

// Closed parts (body, ribs, connector) overlapping where they join.
TriangleMesh MakeMotorHousing(const MotorHousingOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_MOTOR_HOUSING_H_
