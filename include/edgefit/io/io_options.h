// Options shared by the scan readers and writers (PTX, PCD, PLY, E57, depth PNG).
#ifndef EDGEFIT_IO_IO_OPTIONS_H_
#define EDGEFIT_IO_IO_OPTIONS_H_

#include "edgefit/io/camera_info.h"
#include "edgefit/scan/lattice_estimation.h"

namespace edgefit {

struct ReadOptions {
  // Estimate each organized scan's ScanLattice after loading (a scan whose
  // lattice cannot be estimated, e.g. one without valid points, fails the read).
  bool estimate_lattice = true;
  // Keep each point's intensity. A fit never reads it: false holds none
  // (4 bytes per cell; PTX: never allocated, other formats: freed as each
  // scan is finished), and intensity() is 0.
  bool intensity = true;
  LatticeOptions lattice;
  // A depth camera's intrinsics (a ROS camera_info file): a depth PNG needs
  // them; an organized scan read with them takes their projective lattice
  // instead of one estimated from its points (its grid must be the
  // camera's width x height); a point list read with them (a frame whose
  // pixels without a depth were dropped) is put back on the camera's pixel
  // grid, each point on the pixel it projects to. Empty: none.
  CameraInfo camera;
  // Depth PNG: metres per unit of its 16-bit values (ROS: millimetres).
  double depth_scale = 0.001;
  // PTX: detect the rows/columns order and the fast index from the data
  // (DESIGN.md, Formats); false trusts the standard layout (line 1 = columns,
  // line 2 = rows, column by column).
  bool detect_ptx_layout = true;
};

struct WriteOptions {
  // PCD and PLY: binary (little endian) when true, ASCII otherwise. PTX is text.
  bool binary = true;
};

}  // namespace edgefit

#endif  // EDGEFIT_IO_IO_OPTIONS_H_
