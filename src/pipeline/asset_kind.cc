#include "edgefit/pipeline/asset_kind.h"

namespace edgefit {

const char* AssetKindName(AssetKind kind) {
  return kind == AssetKind::kConveyance ? "conveyance" : "articulated";
}

Status ChooseAssetKind(const std::string& name, const KinematicModel& model, AssetKind* kind) {
  if (name == "articulated") {
    *kind = AssetKind::kArticulated;
  } else if (name == "conveyance") {
    *kind = AssetKind::kConveyance;
  } else if (name == "auto") {
    int prismatic = 0, other = 0;
    for (const Joint& j : model.joints()) {
      if (!j.IsIndependent()) continue;
      (j.type == JointType::kPrismatic ? prismatic : other) += 1;
    }
    *kind = prismatic > 0 && other == 0 ? AssetKind::kConveyance : AssetKind::kArticulated;
  } else {
    return Status::Error("--kind must be auto, articulated or conveyance, not '" + name + "'");
  }
  return Status::Ok();
}

FitOptions FitOptionsFor(AssetKind kind) {
  FitOptions options;
  if (kind == AssetKind::kConveyance) {
    options.base.method = BaseOptions::Method::kArmTips;
    options.chain.sweep.max_view_gap = 0.01;
    for (WeightedIcpOptions* icp :
         {&options.base.icp, &options.chain.joint_icp, &options.chain.subtree_icp}) {
      icp->quality_max_view_gap = 0.01;
    }
  }
  return options;
}

}  // namespace edgefit
