// Which pipeline fits a model (`edgefit fit --kind`): an articulated robot
// (paper Sec. 5: the base's rough pose from cross-section corners) or a
// conveyance system (Sec. 6: from the arm tips and their symmetry axis).
// --kind=auto takes a model whose independent joints are all prismatic (and
// at least one) for a conveyance system: a robot on a linear track has
// revolute joints and stays articulated.
#ifndef EDGEFIT_PIPELINE_ASSET_KIND_H_
#define EDGEFIT_PIPELINE_ASSET_KIND_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/fit_options.h"

namespace edgefit {

enum class AssetKind { kArticulated, kConveyance };

const char* AssetKindName(AssetKind kind);  // "articulated", "conveyance"

// "auto" (from the model), "articulated" or "conveyance".
Status ChooseAssetKind(const std::string& name, const KinematicModel& model, AssetKind* kind);

// The default fit options of a kind (conveyance: the arm-tip base rough,
// faces seen edge-on left out of the Eq. 9 sweeps and the quality measure:
// JointSweepOptions::max_view_gap, WeightedIcpOptions::quality_max_view_gap).
FitOptions FitOptionsFor(AssetKind kind);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_ASSET_KIND_H_
