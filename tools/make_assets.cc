// edgefit_make_assets: regenerates the bundled benchmark models (robot with
// welding gun, conveyance system) from the project's own procedural code.
//
//   edgefit_make_assets --out=assets
//
// Writes <out>/robot/... and <out>/conveyor/... (see
// edgefit/assets/benchmark_assets.h). Exit code 2 with one line on failure.
#include <gflags/gflags.h>
#include <glog/logging.h>

#include <iostream>

#include "edgefit/assets/benchmark_assets.h"

DEFINE_string(out, "assets", "Output directory; robot/ and conveyor/ are written under it.");

int main(int argc, char** argv) {
  gflags::SetUsageMessage("Regenerates the benchmark models: edgefit_make_assets --out=assets");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  if (FLAGS_out.empty()) {
    std::cerr << "edgefit_make_assets: --out must not be empty\n";
    return 2;
  }
  const edgefit::Status status = edgefit::GenerateBenchmarkAssets(FLAGS_out);
  if (!status.ok()) {
    std::cerr << "edgefit_make_assets: " << status.message() << "\n";
    return 2;
  }
  std::cout << "wrote " << FLAGS_out << "/robot and " << FLAGS_out << "/conveyor\n";
  return 0;
}
