// The base's rough poses, ranked (an extension of Sec. 5.1.1 / 6.1): the
// rough stage returns candidates; each is scored by the Eq. (9) loss of the
// base alone (with the scan's visibility: parts seen, or space seen empty,
// on one side tell a symmetric base's turns apart, which the 2D scores of
// the cross sections cannot). An elongated base (a linear track's rail)
// first slides each candidate along its length. The best, and distinct
// runners-up nearly as good, go on to be fitted through the whole chain.
#ifndef EDGEFIT_SOLVERS_BASE_BASE_HYPOTHESES_H_
#define EDGEFIT_SOLVERS_BASE_BASE_HYPOTHESES_H_

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "solvers/base/conveyance_base_rough.h"

namespace edgefit {

struct BaseHypothesesOptions {
  // A base more than slide_elongation times longer than wide (a linear
  // track's rail, uniform along its length) fits its cross sections about
  // equally well anywhere along it: each candidate is moved along its
  // length, up to half that length either way, to the lowest Eq. (9) loss
  // of the base (coarse steps of slide_step [m], then a fifth of it). The
  // KUKA on its 8.2 m rail (3 mm scan, no accessories) had its rail put
  // 0.61 m off without it.
  double slide_elongation = 3.0;
  double slide_step = 0.05;  // [m]
  // A base nearly symmetric under a half or quarter turn scores its turned
  // pose nearly as well alone; its links tell the two apart. Up to
  // `alternatives` further rough poses (distinct by 5 degrees or 5 cm)
  // whose base loss is within alternative_loss per sample [m] of the best
  // are fitted through the whole chain too; the lowest Eq. (9) loss of the
  // whole model wins. The bundled conveyor turned half a turn scored 0.34
  // mm/sample worse alone (3 mm spacing, accessories); its whole model 4 %
  // worse. The bundled robot seen from 2 stations (3 mm, `home`) had its
  // base a quarter turn off and said ok with none; one alternative found
  // the right pose for 1.05 s more chain (3: 7.1 s). Where no other rough
  // pose comes near the best it costs nothing (24 bare robots at 1.7 mm);
  // the bundled robot's `home` at 1.7 mm fitted one, about 3 s more.
  int alternatives = 1;
  double alternative_loss = 0.001;  // [m] per sample
  // Extension for cells: an alternative whose base stands farther than this
  // from the best rough pose's [m] is another machine's place (a second
  // robot of the model, found by the next search), not another reading of
  // this one: it is fitted only when the best one's base does not match the
  // scan. Infinite (edgefit fit): every alternative is fitted; the cell fit
  // sets 0.5 m (the demo cell's first robot fitted its twin 2.7 m away, 3 s).
  double instance_separation = std::numeric_limits<double>::infinity();

  bool IsValid(std::string* error) const;
};

// Whether two rough base poses are different answers: more than 5 degrees
// or 5 cm apart (the precise ICP's reach).
bool IsDistinctPose(const Pose& a, const Pose& b);

// T_world_base moved along its own axis `axis_base` by up to +-range [m]
// to the lowest loss: a coarse pass at `step`, then step / 5 around it.
Pose SlideAlong(const Pose& T_world_base, const Eigen::Vector3d& axis_base, double range,
                double step, const BasePoseLoss& loss);

// The rough poses to fit from, best first: *candidates (slid in place along
// the base's long axis first when `base_size` [m], the base mesh's box, is
// elongated and slide is true) ranked by `loss`; the best, then up to
// options.alternatives distinct ones within options.alternative_loss per
// sample (`samples`: the samples the loss scores). say: a line per step.
std::vector<Pose> RankBaseHypotheses(std::vector<Pose>* candidates,
                                     const Eigen::Vector3d& base_size, bool slide,
                                     const BasePoseLoss& loss, size_t samples,
                                     const BaseHypothesesOptions& options,
                                     const std::function<void(const std::string&)>& say);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_BASE_HYPOTHESES_H_
