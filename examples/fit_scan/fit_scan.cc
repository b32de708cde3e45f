// Fits a URDF model to a scan with the installed edgefit library:
//   fit_scan MODEL.urdf SCAN.ptx [SCAN2.ptx ...]
// prints the base pose and every moving joint; exit 0 when the fit matches
// the scan, 1 when it does not, 2 on bad input.
#include <edgefit/io/scan_io.h>
#include <edgefit/model/urdf_loader.h>
#include <edgefit/pipeline/asset_kind.h>
#include <edgefit/pipeline/fit.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MODEL.urdf SCAN.ptx [SCAN2.ptx ...]\n", argv[0]);
    return 2;
  }
  edgefit::KinematicModel model;
  edgefit::ScanSet scans;
  edgefit::Status status = edgefit::LoadKinematicModel(argv[1], {}, &model);
  for (int i = 2; status.ok() && i < argc; ++i) status = edgefit::ReadScans(argv[i], {}, &scans);
  edgefit::AssetKind kind = edgefit::AssetKind::kArticulated;
  if (status.ok()) status = edgefit::ChooseAssetKind("auto", model, &kind);
  edgefit::FitResult fit;
  if (status.ok()) status = edgefit::Fit(model, scans, edgefit::FitOptionsFor(kind), nullptr, &fit);
  if (!status.ok()) {
    std::fprintf(stderr, "fit_scan: %s\n", status.message().c_str());
    return 2;
  }
  const Eigen::Vector3d t = fit.T_world_base.translation();
  std::printf("base at %.4f %.4f %.4f m\n", t.x(), t.y(), t.z());
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const edgefit::Joint& joint = model.joints()[j];
    if (joint.IsMoving()) std::printf("%s %.6f\n", joint.name.c_str(), fit.q[j]);
  }
  std::printf("%s %s\n", fit.ok ? "ok" : "not ok:", fit.message.c_str());
  return fit.ok ? 0 : 1;
}
