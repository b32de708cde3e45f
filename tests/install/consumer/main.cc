// Uses the installed edgefit: a scan grid with its lattice, and a URDF model.
#include <edgefit/core/pose.h>
#include <edgefit/model/urdf_loader.h>
#include <edgefit/scan/organized_scan.h>
#include <edgefit/costs/point_to_point_cost.h>
#include <edgefit/costs/robust_loss.h>

#include <memory>

#include <cstdio>

int main(int argc, char** argv) {
  edgefit::OrganizedScan scan(4, 5);
  scan.SetPoint(scan.Index(1, 2), Eigen::Vector3f(1.0f, 0.0f, 0.0f), 0.5f);
  if (scan.CountValid() != 1) return 1;
  if (argc < 2) return 1;
  edgefit::KinematicModel model;
  const edgefit::Status status =
      edgefit::LoadKinematicModel(argv[1], edgefit::ModelLoadOptions(), &model);
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.message().c_str());
    return 1;
  }
  // Ceres functors from the installed costs/ headers.
  std::unique_ptr<ceres::CostFunction> cost(edgefit::PointToPointCost::Create(
      Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 0), 10.0));
  const double rotation[3] = {0, 0, 0}, translation[3] = {0, 0, 0};
  const double* parameters[2] = {rotation, translation};
  double residuals[3] = {1, 1, 1};
  if (!cost->Evaluate(parameters, residuals, nullptr) || residuals[0] != 0.0) return 1;
  std::unique_ptr<ceres::LossFunction> loss;
  if (!edgefit::MakeLoss("huber", 0.01, &loss).ok()) return 1;
  std::printf("consumer ok: %zu links\n", model.links().size());
  return 0;
}
