#include "edgefit/pipeline/model_points.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "edgefit/model/surface_sampler.h"

namespace edgefit {

std::vector<Eigen::Vector3f> WorldSurfaceSamples(const KinematicModel& model,
                                                 const std::vector<double>& q,
                                                 const Pose& T_world_base, double spacing,
                                                 uint64_t seed) {
  SamplingOptions sampling;
  sampling.spacing = spacing;
  sampling.seed = seed;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  std::vector<Eigen::Vector3f> world;
  for (size_t l = 0; l < samples.size(); ++l) {
    for (const Eigen::Vector3f& p : samples[l].points) {
      world.push_back((T_world_link[l] * p.cast<double>()).cast<float>());
    }
  }
  return world;
}

Status MarkModelPoints(const ScanSet& scans, const KinematicModel& model,
                       const std::vector<double>& q, const Pose& T_world_base,
                       const ModelPointsOptions& options,
                       std::vector<std::vector<uint8_t>>* on_model) {
  CHECK(on_model != nullptr);
  if (q.size() != model.joints().size()) return Status::Error("model points: wrong joint count");
  if (!(options.distance > 0.0) || !(options.sample_spacing > 0.0)) {
    return Status::Error("model points: distance and sample_spacing must be > 0");
  }
  const std::vector<Eigen::Vector3f> p_world =
      WorldSurfaceSamples(model, q, T_world_base, options.sample_spacing, options.seed);

  on_model->assign(scans.scans.size(), {});
  const float max_d2 = static_cast<float>(options.distance * options.distance);
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    std::vector<uint8_t>& marks = (*on_model)[s];
    marks.assign(scan.size(), 0);
    const ScanLattice& lattice = scan.lattice();
    if (!scan.organized() || !lattice.valid() || lattice.rows() != scan.rows() ||
        lattice.cols() != scan.cols()) {
      continue;
    }
    const Pose T_scanner_world = scan.T_world_scanner().inverse();
    const double step = std::min(std::abs(lattice.row_step()), std::abs(lattice.col_step()));
    const int rows = scan.rows(), cols = scan.cols();
    const int64_t n = static_cast<int64_t>(p_world.size());
    // Marking is idempotent (only ever 0 -> 1), so the result does not
    // depend on the schedule.
#pragma omp parallel for schedule(dynamic, 1024)
    for (int64_t i = 0; i < n; ++i) {
      const Eigen::Vector3d p = T_scanner_world * p_world[static_cast<size_t>(i)].cast<double>();
      int row, col;
      if (!lattice.ProjectToCell(p, &row, &col)) continue;
      // Cells whose rays pass within `distance` of p: the window's angular
      // half-width is distance / range (grown by one cell for rounding).
      const int w =
          std::min(64, static_cast<int>(std::ceil(options.distance / (p.norm() * step))) + 1);
      const Eigen::Vector3f pf = p.cast<float>();
      for (int dc = -w; dc <= w; ++dc) {
        int c = col + dc;
        if (c < 0 || c >= cols) {
          if (!lattice.full_circle()) continue;
          c = ((c % cols) + cols) % cols;
        }
        for (int r = std::max(0, row - w); r <= std::min(rows - 1, row + w); ++r) {
          const size_t cell = scan.Index(r, c);
          // Missing cells are NaN: the comparison is false.
          if ((scan.point_scanner(cell) - pf).squaredNorm() <= max_d2) {
#pragma omp atomic write
            marks[cell] = 1;
          }
        }
      }
    }
  }
  return Status::Ok();
}

size_t RemoveMarkedPoints(const std::vector<std::vector<uint8_t>>& marks, ScanSet* scans) {
  CHECK(scans != nullptr);
  CHECK_EQ(marks.size(), scans->scans.size());
  size_t removed = 0;
  for (size_t s = 0; s < scans->scans.size(); ++s) {
    OrganizedScan& scan = scans->scans[s];
    CHECK_EQ(marks[s].size(), scan.size());
    for (size_t cell = 0; cell < scan.size(); ++cell) {
      if (marks[s][cell] != 0 && scan.IsValid(cell)) {
        scan.SetMissing(cell);
        ++removed;
      }
    }
  }
  return removed;
}

}  // namespace edgefit
