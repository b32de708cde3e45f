#include "edgefit/assets/perforated_plate.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

namespace edgefit {
namespace {

constexpr double kGridTolerance = 1e-9;  // [m] coordinates this close are one grid line.

std::vector<double> GridLines(double half_extent, const std::vector<double>& borders) {
  std::vector<double> lines = borders;
  lines.push_back(-half_extent);
  lines.push_back(half_extent);
  std::sort(lines.begin(), lines.end());
  std::vector<double> unique;
  for (double v : lines) {
    if (unique.empty() || v - unique.back() > kGridTolerance) unique.push_back(v);
  }
  return unique;
}

}  // namespace

TriangleMesh MakePerforatedPlate(const PerforatedPlateOptions& options) {
  const int n = options.hole_segments;
  CHECK(n >= 8 && n % 4 == 0) << "hole_segments must be a multiple of 4, >= 8";
  CHECK_GT(options.cell_scale, 1.0);
  CHECK_GT(options.thickness, 0.0);
  const double hx = 0.5 * options.size.x(), hy = 0.5 * options.size.y();
  std::vector<double> x_borders, y_borders;
  for (const PlateHole& hole : options.holes) {
    const double a = options.cell_scale * hole.radius;
    CHECK(hole.centre.x() - a > -hx && hole.centre.x() + a < hx && hole.centre.y() - a > -hy &&
          hole.centre.y() + a < hy)
        << "hole cell outside the plate";
    x_borders.insert(x_borders.end(), {hole.centre.x() - a, hole.centre.x() + a});
    y_borders.insert(y_borders.end(), {hole.centre.y() - a, hole.centre.y() + a});
  }
  const std::vector<double> xs = GridLines(hx, x_borders);
  const std::vector<double> ys = GridLines(hy, y_borders);
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size());
  const double z_top = 0.5 * options.thickness, z_bottom = -z_top;

  TriangleMesh mesh;
  // Grid vertex (i, j) on the top face is 2 * (j * nx + i), on the bottom + 1.
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      mesh.vertices.emplace_back(xs[i], ys[j], z_top);
      mesh.vertices.emplace_back(xs[i], ys[j], z_bottom);
    }
  }
  auto top = [nx](int i, int j) { return 2 * (j * nx + i); };
  auto bottom = [nx](int i, int j) { return 2 * (j * nx + i) + 1; };
  // Both faces at once: a top triangle counter-clockwise about +z and its
  // mirror on the bottom, reversed.
  auto add_face_triangle = [&mesh](int a, int b, int c, int a_bottom, int b_bottom, int c_bottom) {
    mesh.triangles.emplace_back(a, b, c);
    mesh.triangles.emplace_back(a_bottom, c_bottom, b_bottom);
  };

  std::vector<bool> used(options.holes.size(), false);
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const Eigen::Vector2d centre(0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1]));
      int hole_index = -1;
      for (size_t h = 0; h < options.holes.size(); ++h) {
        if ((options.holes[h].centre - centre).norm() < kGridTolerance) hole_index = static_cast<int>(h);
      }
      // Corners counter-clockwise from (x0, y0): top and bottom indices.
      const int ct[4] = {top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1)};
      const int cb[4] = {bottom(i, j), bottom(i + 1, j), bottom(i + 1, j + 1), bottom(i, j + 1)};
      if (hole_index < 0) {
        add_face_triangle(ct[0], ct[1], ct[2], cb[0], cb[1], cb[2]);
        add_face_triangle(ct[0], ct[2], ct[3], cb[0], cb[2], cb[3]);
        continue;
      }
      const PlateHole& hole = options.holes[hole_index];
      const double a = options.cell_scale * hole.radius;
      CHECK(std::abs(xs[i + 1] - xs[i] - 2.0 * a) < 1e-7 && std::abs(ys[j + 1] - ys[j] - 2.0 * a) < 1e-7)
          << "hole " << hole_index << ": its cell is split by another hole's grid lines";
      used[hole_index] = true;
      const int first = static_cast<int>(mesh.vertices.size());
      for (int k = 0; k < n; ++k) {
        const double theta = 2.0 * M_PI * k / n;  // Vertex k = 0, n/4, ... faces a cell side.
        const Eigen::Vector2d p = hole.centre + hole.radius * Eigen::Vector2d(std::cos(theta), std::sin(theta));
        mesh.vertices.emplace_back(p.x(), p.y(), z_top);
        mesh.vertices.emplace_back(p.x(), p.y(), z_bottom);
      }
      auto ht = [first, n](int k) { return first + 2 * (k % n); };
      auto hb = [first, n](int k) { return first + 2 * (k % n) + 1; };
      const int quarter = n / 4;
      // Quadrant q (angles 90q .. 90(q+1)) faces corner (q + 2) % 4: corner
      // 2 is (x1, y1) at 45 deg. Side q (at angle 90q) lies between corners
      // (q + 1) % 4 and (q + 2) % 4.
      for (int q = 0; q < 4; ++q) {
        const int corner = (q + 2) % 4, previous = (q + 1) % 4;
        add_face_triangle(ct[previous], ct[corner], ht(q * quarter), cb[previous], cb[corner],
                          hb(q * quarter));
        for (int k = q * quarter; k < (q + 1) * quarter; ++k) {
          add_face_triangle(ht(k), ct[corner], ht(k + 1), hb(k), cb[corner], hb(k + 1));
        }
      }
      // The hole wall faces the hole's axis.
      for (int k = 0; k < n; ++k) {
        mesh.triangles.emplace_back(hb(k), ht(k + 1), hb(k + 1));
        mesh.triangles.emplace_back(hb(k), ht(k), ht(k + 1));
      }
    }
  }
  for (size_t h = 0; h < used.size(); ++h) CHECK(used[h]) << "hole " << h << " not on the grid";
  // Outer walls: the grid's boundary counter-clockwise about +z.
  std::vector<std::pair<int, int>> boundary;
  for (int i = 0; i + 1 < nx; ++i) boundary.emplace_back(i, 0);
  for (int j = 0; j + 1 < ny; ++j) boundary.emplace_back(nx - 1, j);
  for (int i = nx - 1; i > 0; --i) boundary.emplace_back(i, ny - 1);
  for (int j = ny - 1; j > 0; --j) boundary.emplace_back(0, j);
  for (size_t k = 0; k < boundary.size(); ++k) {
    const auto [i0, j0] = boundary[k];
    const auto [i1, j1] = boundary[(k + 1) % boundary.size()];
    mesh.triangles.emplace_back(bottom(i0, j0), bottom(i1, j1), top(i1, j1));
    mesh.triangles.emplace_back(bottom(i0, j0), top(i1, j1), top(i0, j0));
  }
  return mesh;
}

}  // namespace edgefit
