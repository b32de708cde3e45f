#include "solvers/refinement/coverings.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace edgefit {

namespace {

// The cells of `scan` no sample matched (owner -1) take the verdict of the
// nearest matched cell within `window` lattice cells and `gate` metres,
// counted in *summary under that cell's link. Distances in the scanner's
// frame (rigid: the same as in the world's, without a transform per pair).
void SpreadVerdicts(const OrganizedScan& scan, const std::vector<int>& owner, int window,
                    double gate, std::vector<uint8_t>* covered, CoveringSummary* summary) {
  const int rows = scan.rows(), cols = scan.cols();
  std::vector<int> from(scan.size(), -1);
  std::vector<int> from_distance(scan.size(), std::numeric_limits<int>::max());
  for (int c = 0; c < cols; ++c) {
    for (int r = 0; r < rows; ++r) {
      const size_t cell = scan.Index(r, c);
      if (owner[cell] < 0) continue;
      const Eigen::Vector3d p = scan.point_scanner(cell).cast<double>();
      for (int cc = std::max(0, c - window); cc <= std::min(cols - 1, c + window); ++cc) {
        for (int rr = std::max(0, r - window); rr <= std::min(rows - 1, r + window); ++rr) {
          const size_t other = scan.Index(rr, cc);
          const int d = (cc - c) * (cc - c) + (rr - r) * (rr - r);
          if (owner[other] >= 0 || !scan.IsValid(other) || d >= from_distance[other] ||
              (scan.point_scanner(other).cast<double>() - p).squaredNorm() > gate * gate) {
            continue;
          }
          from_distance[other] = d;
          from[other] = static_cast<int>(cell);
        }
      }
    }
  }
  for (size_t cell = 0; cell < scan.size(); ++cell) {
    if (from[cell] < 0) continue;
    const size_t judged = static_cast<size_t>(from[cell]);
    const size_t link = static_cast<size_t>(owner[judged]);
    ++summary->matched;
    ++summary->link_matched[link];
    if (!(*covered)[judged]) continue;
    (*covered)[cell] = 1;
    ++summary->covered;
    ++summary->link_covered[link];
  }
}

}  // namespace

bool CoveringOptions::IsValid(std::string* error) const {
  if (rounds < 0 || window < 0 || window > 20) {
    *error = "coverings: rounds must be >= 0 and window 0..20";
  } else if (!(gate > 0.0 && area_offset > 0.0 && point_offset >= area_offset) ||
             !(refit_share > 0.0)) {
    *error = "coverings: need gate > 0, 0 < area_offset <= point_offset, refit_share > 0";
  } else {
    return true;
  }
  return false;
}

bool CoveringsHideALink(const CoveringSummary& summary, const CoveringOptions& options) {
  for (size_t l = 0; l < summary.link_matched.size(); ++l) {
    if (summary.link_matched[l] > 0 && summary.Share(l) >= options.refit_share) return true;
  }
  return false;
}

Status FindCoverings(const KinematicModel& model, const ScanSet& scans,
                     CorrespondenceSearch* search, const std::vector<SurfaceSamples>& link_samples,
                     const Pose& T_world_base, const std::vector<double>& q,
                     const CoveringOptions& options, bool use_lattice, CellMask* covered,
                     CoveringSummary* summary) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error(error);
  if (link_samples.size() != model.links().size() || q.size() != model.joints().size()) {
    return Status::Error("coverings: samples or joint values do not match the model");
  }
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  const size_t n_scans = scans.scans.size();
  // Per cell: signed distance of its closest sample, that distance, its link.
  constexpr float kNone = std::numeric_limits<float>::infinity();
  std::vector<std::vector<float>> offset(n_scans), closest(n_scans);
  std::vector<std::vector<int>> owner(n_scans);
  for (size_t s = 0; s < n_scans; ++s) {
    offset[s].assign(scans.scans[s].size(), 0.0f);
    closest[s].assign(scans.scans[s].size(), kNone);
    owner[s].assign(scans.scans[s].size(), -1);
  }
  CorrespondenceOptions correspondence;
  correspondence.max_distance = options.gate;
  correspondence.use_lattice = use_lattice;
  std::vector<Correspondence> matches, per_scan;
  for (size_t l = 0; l < link_samples.size(); ++l) {
    const SurfaceSamples& samples = link_samples[l];
    if (samples.points.empty()) continue;
    const Pose& T = T_world_link[l];
    std::vector<Eigen::Vector3f> q_world(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
      q_world[i] = (T * samples.points[i].cast<double>()).cast<float>();
    }
    // The lattice: the nearest cell in every scan, so that each scanner's
    // view of a covering is judged (the nearest over all scans would leave
    // the farther views of a thick jacket unjudged); the kd-tree: the
    // nearest over all scans.
    matches.clear();
    if (use_lattice) {
      const float max_d2 = static_cast<float>(options.gate * options.gate);
      for (size_t s = 0; s < n_scans; ++s) {
        per_scan.assign(q_world.size(), Correspondence());
#pragma omp parallel for schedule(dynamic, 512)
        for (int64_t i = 0; i < static_cast<int64_t>(q_world.size()); ++i) {
          per_scan[static_cast<size_t>(i)] = search->lattice().NearestIn(
              static_cast<int>(s), q_world[static_cast<size_t>(i)], correspondence.window, max_d2);
          per_scan[static_cast<size_t>(i)].source = static_cast<int>(i);
        }
        for (const Correspondence& c : per_scan) {
          if (c.scan >= 0) matches.push_back(c);
        }
      }
    } else {
      Eigen::AlignedBox3d crop;
      for (const Eigen::Vector3f& x : q_world) crop.extend(x.cast<double>());
      crop.min().array() -= options.gate;
      crop.max().array() += options.gate;
      search->Find(q_world, crop, correspondence, &matches);
    }
    for (const Correspondence& c : matches) {
      const OrganizedScan& scan = scans.scans[static_cast<size_t>(c.scan)];
      const Eigen::Vector3d q_i = q_world[static_cast<size_t>(c.source)].cast<double>();
      const Eigen::Vector3d n_i =
          T.linear() * samples.normals[static_cast<size_t>(c.source)].cast<double>();
      if (n_i.dot(scan.T_world_scanner().translation() - q_i) <= 0.0) continue;  // back face
      float& best = closest[static_cast<size_t>(c.scan)][static_cast<size_t>(c.cell)];
      if (!(c.distance < best)) continue;
      best = c.distance;
      offset[static_cast<size_t>(c.scan)][static_cast<size_t>(c.cell)] =
          static_cast<float>(n_i.dot(scan.PointWorld(static_cast<size_t>(c.cell)) - q_i));
      owner[static_cast<size_t>(c.scan)][static_cast<size_t>(c.cell)] = static_cast<int>(l);
    }
  }

  // A link a prismatic joint slides is never covered (coverings.h).
  std::vector<bool> slides(model.links().size(), false);
  for (const Joint& j : model.joints()) {
    if (j.type == JointType::kPrismatic) slides[static_cast<size_t>(j.child_link)] = true;
  }

  *summary = CoveringSummary();
  summary->link_matched.assign(model.links().size(), 0);
  summary->link_covered.assign(model.links().size(), 0);
  covered->assign(n_scans, {});
  std::vector<float> block;
  for (size_t s = 0; s < n_scans; ++s) {
    const OrganizedScan& scan = scans.scans[s];
    (*covered)[s].assign(scan.size(), 0);
    const int rows = scan.rows(), cols = scan.cols();
    const int w = scan.organized() ? options.window : 0;
    for (int c = 0; c < cols; ++c) {
      for (int r = 0; r < rows; ++r) {
        const size_t cell = scan.Index(r, c);
        if (owner[s][cell] < 0) continue;
        block.clear();
        for (int cc = std::max(0, c - w); cc <= std::min(cols - 1, c + w); ++cc) {
          for (int rr = std::max(0, r - w); rr <= std::min(rows - 1, r + w); ++rr) {
            const size_t other = scan.Index(rr, cc);
            if (owner[s][other] >= 0) block.push_back(offset[s][other]);
          }
        }
        std::nth_element(block.begin(), block.begin() + block.size() / 2, block.end());
        const size_t link = static_cast<size_t>(owner[s][cell]);
        const bool is_covering = !slides[link] && (block[block.size() / 2] > options.area_offset ||
                                                   offset[s][cell] > options.point_offset);
        ++summary->matched;
        ++summary->link_matched[link];
        if (!is_covering) continue;
        (*covered)[s][cell] = 1;
        ++summary->covered;
        ++summary->link_covered[link];
      }
    }
    if (w > 0) SpreadVerdicts(scan, owner[s], w, options.gate, &(*covered)[s], summary);
  }
  return Status::Ok();
}

}  // namespace edgefit
