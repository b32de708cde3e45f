#include "solvers/registration/station_alignment.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "edgefit/correspondence/lattice_search.h"

namespace edgefit {
namespace {

// The rigid motion x -> R(omega) (x - c) + c + t.
Pose MotionAbout(const Eigen::Vector3d& omega, const Eigen::Vector3d& t, const Eigen::Vector3d& c) {
  Pose D = Pose::Identity();
  if (omega.norm() > 0.0) {
    D.linear() = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
  }
  D.translation() = c + t - D.linear() * c;
  return D;
}

// (omega, t) of a motion about c.
Eigen::Matrix<double, 6, 1> Log(const Pose& D, const Eigen::Vector3d& c) {
  const Eigen::AngleAxisd aa(D.linear());
  Eigen::Matrix<double, 6, 1> x;
  x << aa.angle() * aa.axis(), D * c - c;
  return x;
}

}  // namespace

bool StationAlignmentOptions::IsValid(std::string* error) const {
  if (!(max_distance > 0.0 && final_gate > 0.0 && final_gate <= max_distance)) {
    *error = "station alignment: need 0 < final_gate <= max_distance";
  } else if (!(huber_scale > 0.0) || iterations < 1 || lattice_window < 0) {
    *error = "station alignment: huber_scale and iterations must be positive";
  } else if (!(prior_translation > 0.0 && prior_rotation > 0.0 && point_sigma > 0.0)) {
    *error = "station alignment: the prior's sigmas must be positive";
  } else if (rounds < 1) {
    *error = "station alignment: need rounds >= 1";
  } else if (!(settled_change >= 0.0)) {
    *error = "station alignment: settled_change must be >= 0";
  } else if (!(max_covered_share >= 0.0 && max_covered_share <= 1.0)) {
    *error = "station alignment: max_covered_share must be in [0, 1]";
  } else {
    return true;
  }
  return false;
}

Status AlignStationsToModel(const KinematicModel& model,
                            const std::vector<SurfaceSamples>& link_samples,
                            const Pose& T_world_base, const std::vector<double>& q,
                            const std::vector<std::vector<uint8_t>>* excluded,
                            const std::vector<uint8_t>& links_left_out,
                            const StationAlignmentOptions& options, ScanSet* scans,
                            StationAlignmentSummary* summary) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error(error);
  if (link_samples.size() != model.links().size() || q.size() != model.joints().size() ||
      (!links_left_out.empty() && links_left_out.size() != model.links().size())) {
    return Status::Error("station alignment: samples or joint values do not match the model");
  }
  *summary = StationAlignmentSummary();
  summary->links_left_out = links_left_out;
  const size_t n = scans->scans.size();
  if (!options.align || n < 2) return Status::Ok();

  // The posed model: points and normals in the world, and its centre.
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3d> normals;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (size_t l = 0; l < link_samples.size(); ++l) {
    const SurfaceSamples& samples = link_samples[l];
    if (samples.normals.size() != samples.points.size()) continue;
    if (!links_left_out.empty() && links_left_out[l]) continue;
    for (size_t i = 0; i < samples.points.size(); ++i) {
      const Eigen::Vector3d p = T_world_link[l] * samples.points[i].cast<double>();
      points.push_back(p.cast<float>());
      normals.push_back(T_world_link[l].linear() * samples.normals[i].cast<double>());
      centre += p;
    }
  }
  if (points.empty()) return Status::Ok();
  centre /= static_cast<double>(points.size());

  const Eigen::Matrix<double, 6, 1> prior =
      (Eigen::Matrix<double, 6, 1>()
           << Eigen::Vector3d::Constant(std::pow(options.point_sigma / options.prior_rotation, 2)),
       Eigen::Vector3d::Constant(std::pow(options.point_sigma / options.prior_translation, 2)))
          .finished();
  std::vector<Pose> D(n, Pose::Identity());
  std::vector<Pose> T_written(n);
  for (size_t s = 0; s < n; ++s) T_written[s] = scans->scans[s].T_world_scanner();
  summary->stations.resize(n);
  for (size_t s = 0; s < n; ++s) {
    OrganizedScan& scan = scans->scans[s];
    // The samples facing this station.
    std::vector<Eigen::Vector3f> facing;
    std::vector<size_t> index;
    for (size_t i = 0; i < points.size(); ++i) {
      if (normals[i].dot(T_written[s].translation() - points[i].cast<double>()) > 0.0) {
        facing.push_back(points[i]);
        index.push_back(i);
      }
    }
    // Point-to-plane residuals at the current correction, and one GN step.
    auto step = [&](double gate, bool solve, size_t* matches, double* rms) {
      scan.set_T_world_scanner(D[s] * T_written[s]);
      LatticeSearch search(scans, nullptr);
      CorrespondenceOptions correspondence;
      correspondence.max_distance = gate;
      correspondence.window = options.lattice_window;
      std::vector<Correspondence> found;
      search.FindIn(static_cast<int>(s), facing, correspondence, &found);
      Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
      double sum2 = 0.0;
      *matches = 0;
      for (const Correspondence& c : found) {
        if (excluded != nullptr && (*excluded)[s][static_cast<size_t>(c.cell)]) continue;
        const Eigen::Vector3d& nrm = normals[index[static_cast<size_t>(c.source)]];
        const Eigen::Vector3d p = scan.PointWorld(static_cast<size_t>(c.cell));
        const double r = nrm.dot(p - facing[static_cast<size_t>(c.source)].cast<double>());
        const double w =
            std::abs(r) <= options.huber_scale ? 1.0 : options.huber_scale / std::abs(r);
        Eigen::Matrix<double, 6, 1> J;
        J << (p - centre).cross(nrm), nrm;
        H += w * J * J.transpose();
        g += w * J * r;
        sum2 += r * r;
        ++*matches;
      }
      *rms = *matches > 0 ? std::sqrt(sum2 / static_cast<double>(*matches)) : 0.0;
      if (!solve || *matches < 12) return;
      const Eigen::Matrix<double, 6, 1> total = Log(D[s], centre);
      H.diagonal() += prior;
      g += prior.cwiseProduct(total);
      const Eigen::Matrix<double, 6, 1> delta = -H.ldlt().solve(g);
      D[s] = MotionAbout(delta.head<3>(), delta.tail<3>(), centre) * D[s];
    };
    StationCorrection& c = summary->stations[s];
    step(options.final_gate, false, &c.matches, &c.rms_before);
    double gate = options.max_distance;
    for (int it = 0; it < options.iterations; ++it) {
      size_t matches = 0;
      double rms = 0.0;
      step(gate, true, &matches, &rms);
      gate = std::max(options.final_gate, 0.5 * gate);
    }
    step(options.final_gate, false, &c.matches, &c.rms_after);
    scan.set_T_world_scanner(T_written[s]);  // until the gauge below
  }

  // Gauge: take out the mean correction (about the centre).
  Eigen::Matrix<double, 6, 1> mean = Eigen::Matrix<double, 6, 1>::Zero();
  for (size_t s = 0; s < n; ++s) mean += Log(D[s], centre);
  mean /= static_cast<double>(n);
  const Pose M = MotionAbout(mean.head<3>(), mean.tail<3>(), centre);
  for (size_t s = 0; s < n; ++s) {
    StationCorrection& c = summary->stations[s];
    c.correction = M.inverse() * D[s];
    const Pose T_aligned = c.correction * T_written[s];
    c.translation = (T_aligned.translation() - T_written[s].translation()).norm();
    c.rotation = Eigen::AngleAxisd(c.correction.linear()).angle();
    scans->scans[s].set_T_world_scanner(T_aligned);
  }
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

double LargestCorrection(const StationAlignmentSummary& summary) {
  double largest = 0.0;
  for (const StationCorrection& c : summary.stations) {
    largest = std::max(largest, c.translation + 5.0 * c.rotation);
  }
  return largest;
}

double LargestChange(const StationAlignmentSummary& before, const StationAlignmentSummary& after,
                     const std::vector<Pose>& T_world_written) {
  if (before.stations.size() != after.stations.size() ||
      before.stations.size() != T_world_written.size()) {
    return std::numeric_limits<double>::infinity();
  }
  double largest = 0.0;
  for (size_t s = 0; s < T_world_written.size(); ++s) {
    const Pose& a = before.stations[s].correction;
    const Pose& b = after.stations[s].correction;
    const Eigen::Vector3d origin = T_world_written[s].translation();
    const double angle = Eigen::AngleAxisd(b.linear() * a.linear().transpose()).angle();
    largest = std::max(largest, (b * origin - a * origin).norm() + 5.0 * angle);
  }
  return largest;
}

std::string StationAlignmentLine(const StationAlignmentSummary& summary) {
  double translation = 0.0, rotation = 0.0, before = 0.0;
  for (const StationCorrection& c : summary.stations) {
    translation = std::max(translation, c.translation);
    rotation = std::max(rotation, c.rotation);
    before = std::max(before, c.rms_before);
  }
  int left_out = 0;
  for (const uint8_t l : summary.links_left_out) left_out += l;
  char line[240];
  std::snprintf(line, sizeof(line),
                "stations: %zu aligned to the model (point-to-plane RMS up to %.2f mm before; %d "
                "links mostly covered left out), largest correction %.2f mm, %.4f deg, %.2f s",
                summary.stations.size(), 1e3 * before, left_out, 1e3 * translation,
                rotation * 180.0 / M_PI, summary.seconds);
  return line;
}

}  // namespace edgefit
