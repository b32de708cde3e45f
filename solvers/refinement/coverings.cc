#include "solvers/refinement/coverings.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace edgefit {

namespace {

// The part of a scan's grid the coverings are judged in: the rows and
// columns of its matched cells and `margin` cells around them, so that the
// per-cell work follows the model rather than the scan.
struct Window {
  int r0 = 0, c0 = 0, rows = 0, cols = 0;
  size_t size() const { return static_cast<size_t>(rows) * static_cast<size_t>(cols); }
  size_t Local(int r, int c) const {
    return static_cast<size_t>(c - c0) * static_cast<size_t>(rows) + static_cast<size_t>(r - r0);
  }
  int RowOf(size_t local) const { return r0 + static_cast<int>(local % static_cast<size_t>(rows)); }
  int ColOf(size_t local) const { return c0 + static_cast<int>(local / static_cast<size_t>(rows)); }
};

// One CAD sample's match in a scan: the cell, the distance, the signed
// distance along the sample's normal (outside positive), the sample's link.
struct Match {
  size_t cell = 0;
  float distance = 0.f, offset = 0.f;
  int link = -1;
};

Window MatchedWindow(const OrganizedScan& scan, const std::vector<Match>& matches, int margin) {
  Window w;
  if (matches.empty()) return w;
  int r0 = scan.rows(), r1 = -1, c0 = scan.cols(), c1 = -1;
  for (const Match& m : matches) {
    const int r = scan.RowOf(m.cell), c = scan.ColOf(m.cell);
    r0 = std::min(r0, r);
    r1 = std::max(r1, r);
    c0 = std::min(c0, c);
    c1 = std::max(c1, c);
  }
  w.r0 = std::max(0, r0 - margin);
  w.c0 = std::max(0, c0 - margin);
  w.rows = std::min(scan.rows() - 1, r1 + margin) - w.r0 + 1;
  w.cols = std::min(scan.cols() - 1, c1 + margin) - w.c0 + 1;
  return w;
}

// The cells of `scan` no sample matched (owner -1, per window cell) take the
// verdict of the nearest matched cell within `window` lattice cells and
// `gate` metres, counted in *summary under that cell's link. Distances in
// the scanner's frame (rigid: the same as in the world's, without a
// transform per pair).
void SpreadVerdicts(const OrganizedScan& scan, const Window& area, const std::vector<int>& owner,
                    int window, double gate, std::vector<uint8_t>* covered,
                    CoveringSummary* summary) {
  const int r_end = area.r0 + area.rows - 1, c_end = area.c0 + area.cols - 1;
  std::vector<int> from(area.size(), -1);  // window index of the judging cell
  std::vector<int> from_distance(area.size(), std::numeric_limits<int>::max());
  for (int c = area.c0; c <= c_end; ++c) {
    for (int r = area.r0; r <= r_end; ++r) {
      const size_t local = area.Local(r, c);
      if (owner[local] < 0) continue;
      const Eigen::Vector3d p = scan.point_scanner(scan.Index(r, c)).cast<double>();
      for (int cc = std::max(area.c0, c - window); cc <= std::min(c_end, c + window); ++cc) {
        for (int rr = std::max(area.r0, r - window); rr <= std::min(r_end, r + window); ++rr) {
          const size_t other = area.Local(rr, cc);
          const size_t other_cell = scan.Index(rr, cc);
          const int d = (cc - c) * (cc - c) + (rr - r) * (rr - r);
          if (owner[other] >= 0 || !scan.IsValid(other_cell) || d >= from_distance[other] ||
              (scan.point_scanner(other_cell).cast<double>() - p).squaredNorm() > gate * gate) {
            continue;
          }
          from_distance[other] = d;
          from[other] = static_cast<int>(local);
        }
      }
    }
  }
  for (size_t local = 0; local < area.size(); ++local) {
    if (from[local] < 0) continue;
    const size_t judged = static_cast<size_t>(from[local]);
    const size_t link = static_cast<size_t>(owner[judged]);
    ++summary->matched;
    ++summary->link_matched[link];
    if (!(*covered)[scan.Index(area.RowOf(judged), area.ColOf(judged))]) continue;
    (*covered)[scan.Index(area.RowOf(local), area.ColOf(local))] = 1;
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
  // Every front-facing match, per scan, in the order links and samples come.
  std::vector<std::vector<Match>> scan_matches(n_scans);
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
      Match m;
      m.cell = static_cast<size_t>(c.cell);
      m.distance = c.distance;
      m.offset = static_cast<float>(n_i.dot(scan.PointWorld(m.cell) - q_i));
      m.link = static_cast<int>(l);
      scan_matches[static_cast<size_t>(c.scan)].push_back(m);
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
    const int w = scan.organized() ? options.window : 0;
    const Window area = MatchedWindow(scan, scan_matches[s], w);
    // Per window cell: the signed distance of its closest sample, that
    // distance, its link (the first of equally close ones).
    std::vector<float> offset(area.size(), 0.0f);
    std::vector<float> closest(area.size(), std::numeric_limits<float>::infinity());
    std::vector<int> owner(area.size(), -1);
    for (const Match& m : scan_matches[s]) {
      const size_t local = area.Local(scan.RowOf(m.cell), scan.ColOf(m.cell));
      if (!(m.distance < closest[local])) continue;
      closest[local] = m.distance;
      offset[local] = m.offset;
      owner[local] = m.link;
    }
    const int r_end = area.r0 + area.rows - 1, c_end = area.c0 + area.cols - 1;
    for (int c = area.c0; c <= c_end; ++c) {
      for (int r = area.r0; r <= r_end; ++r) {
        const size_t local = area.Local(r, c);
        if (owner[local] < 0) continue;
        block.clear();
        for (int cc = std::max(area.c0, c - w); cc <= std::min(c_end, c + w); ++cc) {
          for (int rr = std::max(area.r0, r - w); rr <= std::min(r_end, r + w); ++rr) {
            const size_t other = area.Local(rr, cc);
            if (owner[other] >= 0) block.push_back(offset[other]);
          }
        }
        std::nth_element(block.begin(), block.begin() + block.size() / 2, block.end());
        const size_t link = static_cast<size_t>(owner[local]);
        const bool is_covering = !slides[link] && (block[block.size() / 2] > options.area_offset ||
                                                   offset[local] > options.point_offset);
        ++summary->matched;
        ++summary->link_matched[link];
        if (!is_covering) continue;
        (*covered)[s][scan.Index(r, c)] = 1;
        ++summary->covered;
        ++summary->link_covered[link];
      }
    }
    if (w > 0) SpreadVerdicts(scan, area, owner, w, options.gate, &(*covered)[s], summary);
  }
  return Status::Ok();
}

}  // namespace edgefit
