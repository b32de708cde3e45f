// Uses the installed edgefit: a scan grid with its lattice, and a URDF model.
#include <edgefit/core/pose.h>
#include <edgefit/model/urdf_loader.h>
#include <edgefit/scan/organized_scan.h>

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
  std::printf("consumer ok: %zu links\n", model.links().size());
  return 0;
}
