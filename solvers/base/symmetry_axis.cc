#include "solvers/base/symmetry_axis.h"

#include <algorithm>
#include <limits>

#include "edgefit/core/split_mix64.h"

namespace edgefit {

bool SymmetryAxisOptions::IsValid(std::string* error) const {
  if (!(tolerance > 0.0) || !(min_pair_width >= 0.0) || iterations < 1 || max_axes < 1 ||
      !(distinct_angle >= 0.0) || !(distinct_offset >= 0.0)) {
    if (error != nullptr) {
      *error =
          "symmetry axis: tolerance must be > 0, iterations and max_axes >= 1, "
          "the others >= 0";
    }
    return false;
  }
  return true;
}

Eigen::Vector2d SymmetryAxis::Mirror(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d normal(-direction.y(), direction.x());
  return p - 2.0 * normal.dot(p - point) * normal;
}

namespace {

// Pairs the tips mirrored by `axis`: each tip with the nearest tip to its
// mirror image (within tolerance, heights too), each tip in one pair at
// most, closest matches first.
void PairTips(const std::vector<Eigen::Vector3d>& tips, double tolerance, SymmetryAxis* axis) {
  struct Match {
    double d2;
    int a, b;
  };
  std::vector<Match> matches;
  const double tolerance2 = tolerance * tolerance;
  for (size_t a = 0; a < tips.size(); ++a) {
    const Eigen::Vector2d mirrored = axis->Mirror(tips[a].head<2>());
    for (size_t b = a + 1; b < tips.size(); ++b) {
      if (std::abs(tips[a].z() - tips[b].z()) > tolerance) continue;
      const double d2 = (mirrored - tips[b].head<2>()).squaredNorm();
      if (d2 <= tolerance2) matches.push_back({d2, static_cast<int>(a), static_cast<int>(b)});
    }
  }
  std::sort(matches.begin(), matches.end(), [](const Match& x, const Match& y) {
    return x.d2 != y.d2 ? x.d2 < y.d2 : (x.a != y.a ? x.a < y.a : x.b < y.b);
  });
  std::vector<bool> used(tips.size(), false);
  axis->pairs.clear();
  double sum = 0.0;
  for (const Match& m : matches) {
    if (used[static_cast<size_t>(m.a)] || used[static_cast<size_t>(m.b)]) continue;
    used[static_cast<size_t>(m.a)] = used[static_cast<size_t>(m.b)] = true;
    axis->pairs.emplace_back(m.a, m.b);
    sum += m.d2;
  }
  axis->rms = axis->pairs.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(axis->pairs.size()));
}

// The perpendicular bisector of tips a and b.
SymmetryAxis Bisector(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  SymmetryAxis axis;
  const Eigen::Vector2d across = (b - a).head<2>().normalized();
  axis.direction = Eigen::Vector2d(-across.y(), across.x());
  axis.point = 0.5 * (a + b).head<2>();
  return axis;
}

// Least squares over the pairs: the axis normal is the mean (sign-aligned)
// direction across the pairs, the axis passes through their midpoints' mean.
void Refine(const std::vector<Eigen::Vector3d>& tips, SymmetryAxis* axis) {
  const Eigen::Vector2d normal(-axis->direction.y(), axis->direction.x());
  Eigen::Vector2d across_sum = Eigen::Vector2d::Zero(), mid_sum = Eigen::Vector2d::Zero();
  for (const auto& [a, b] : axis->pairs) {
    Eigen::Vector2d across =
        (tips[static_cast<size_t>(b)] - tips[static_cast<size_t>(a)]).head<2>().normalized();
    if (across.dot(normal) < 0.0) across = -across;
    across_sum += across;
    mid_sum += 0.5 * (tips[static_cast<size_t>(a)] + tips[static_cast<size_t>(b)]).head<2>();
  }
  const Eigen::Vector2d n = across_sum.normalized();
  axis->direction = Eigen::Vector2d(-n.y(), n.x());
  axis->point = mid_sum / static_cast<double>(axis->pairs.size());
}

bool Better(const SymmetryAxis& x, const SymmetryAxis& y) {
  return x.pairs.size() != y.pairs.size() ? x.pairs.size() > y.pairs.size() : x.rms < y.rms;
}

}  // namespace

std::vector<SymmetryAxis> FindSymmetryAxes(const std::vector<Eigen::Vector3d>& tips,
                                           const SymmetryAxisOptions& options) {
  // The hypotheses: every admissible pair (about equal heights, apart by
  // min_pair_width), or `iterations` of them drawn.
  std::vector<std::pair<int, int>> hypotheses;
  const double min_width2 = options.min_pair_width * options.min_pair_width;
  for (size_t a = 0; a < tips.size(); ++a) {
    for (size_t b = a + 1; b < tips.size(); ++b) {
      if (std::abs(tips[a].z() - tips[b].z()) <= options.tolerance &&
          (tips[a] - tips[b]).head<2>().squaredNorm() >= std::max(min_width2, 1e-18)) {
        hypotheses.emplace_back(static_cast<int>(a), static_cast<int>(b));
      }
    }
  }
  if (hypotheses.size() > static_cast<size_t>(options.iterations)) {
    SplitMix64 random(options.seed);  // a seeded partial shuffle
    for (size_t k = 0; k < static_cast<size_t>(options.iterations); ++k) {
      const size_t pick =
          k + static_cast<size_t>(random.Next() % static_cast<uint64_t>(hypotheses.size() - k));
      std::swap(hypotheses[k], hypotheses[pick]);
    }
    hypotheses.resize(static_cast<size_t>(options.iterations));
  }
  std::vector<SymmetryAxis> scored;
  for (const auto& [a, b] : hypotheses) {
    SymmetryAxis axis = Bisector(tips[static_cast<size_t>(a)], tips[static_cast<size_t>(b)]);
    PairTips(tips, options.tolerance, &axis);
    if (axis.pairs.empty()) continue;
    Refine(tips, &axis);
    PairTips(tips, options.tolerance, &axis);
    if (!axis.pairs.empty()) scored.push_back(std::move(axis));
  }
  std::stable_sort(scored.begin(), scored.end(), Better);
  std::vector<SymmetryAxis> distinct;
  for (SymmetryAxis& axis : scored) {
    bool is_new = true;
    for (const SymmetryAxis& kept : distinct) {
      const double angle = std::acos(std::min(1.0, std::abs(axis.direction.dot(kept.direction))));
      const Eigen::Vector2d normal(-kept.direction.y(), kept.direction.x());
      const double offset = std::abs(normal.dot(axis.point - kept.point));
      if (angle <= options.distinct_angle && offset <= options.distinct_offset) is_new = false;
    }
    if (!is_new) continue;
    distinct.push_back(std::move(axis));
    if (static_cast<int>(distinct.size()) == options.max_axes) break;
  }
  return distinct;
}

}  // namespace edgefit
