// Joints not trusted for their neighbours' sake (joint_trust.h).
#include "edgefit/pipeline/joint_trust.h"

#include <algorithm>
#include <vector>

#include "solvers/joints/body.h"

namespace edgefit {
namespace {

// A body matches the scan when it is seen and its samples lie on it.
bool Matches(const BodyQuality& b) {
  return b.verdict != JointVerdict::kMismatch && b.verdict != JointVerdict::kNotSeen;
}

}  // namespace

void DistrustBelowUnmatched(const KinematicModel& model, FitResult* result) {
  std::vector<const BodyQuality*> body_of_link(model.links().size(), nullptr);
  for (const BodyQuality& b : result->bodies) {
    const int link = model.LinkIndex(b.link);
    if (link >= 0) body_of_link[static_cast<size_t>(link)] = &b;
  }
  auto chain_matches = [&](int joint) {
    for (int link = model.joints()[static_cast<size_t>(joint)].parent_link; link >= 0;) {
      const BodyQuality* body = body_of_link[static_cast<size_t>(link)];
      if (body != nullptr && !Matches(*body)) return false;
      const int up = model.links()[static_cast<size_t>(link)].parent_joint;
      link = up < 0 ? -1 : model.joints()[static_cast<size_t>(up)].parent_link;
    }
    return true;
  };
  for (BodyQuality& b : result->bodies) {
    if (b.verdict != JointVerdict::kOk || b.joint.empty()) continue;
    if (chain_matches(model.JointIndex(b.joint))) continue;
    b.verdict = JointVerdict::kAmbiguous;
    b.chain_unmatched = true;
    b.ok = false;
  }
}

void DistrustTornPairs(const KinematicModel& model, FitResult* result) {
  if (!(result->noise_scale > 1.0)) return;
  // Ambiguous on its own: two values of its body fit about equally, not for
  // a neighbour's sake (judged before this rule changes any verdict).
  std::vector<bool> torn(result->bodies.size(), false);
  for (size_t i = 0; i < result->bodies.size(); ++i) {
    const BodyQuality& b = result->bodies[i];
    torn[i] = b.verdict == JointVerdict::kAmbiguous && !b.unpinned && !b.chain_unmatched &&
              !b.partner_torn;
  }
  auto distrust = [&](BodyQuality* b, const BodyQuality& partner) {
    if (b->verdict != JointVerdict::kOk) return;
    b->verdict = JointVerdict::kAmbiguous;
    b->partner_torn = true;
    b->torn_partner = partner.joint;
    b->ok = false;
  };
  for (size_t i = 0; i < result->bodies.size(); ++i) {
    const BodyQuality& round = result->bodies[i];
    if (!round.symmetric || round.joint.empty()) continue;
    const int joint = model.JointIndex(round.joint);
    const Body body = MakeBody(model, model.joints()[static_cast<size_t>(joint)].child_link, joint);
    for (size_t k = 0; k < result->bodies.size(); ++k) {  // its partner: the first joint below
      const int p = model.JointIndex(result->bodies[k].joint);
      if (p < 0) continue;
      const int above = model.joints()[static_cast<size_t>(p)].parent_link;
      if (std::find(body.links.begin(), body.links.end(), above) == body.links.end()) continue;
      if (torn[k]) distrust(&result->bodies[i], result->bodies[k]);
      if (torn[i]) distrust(&result->bodies[k], result->bodies[i]);
      break;
    }
  }
}

}  // namespace edgefit
