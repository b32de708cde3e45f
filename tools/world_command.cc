// edgefit world: the fitted machines as a world that motion planners load
// (include/edgefit/world/planning_world.h says what is written).
//   edgefit world --result=robot.json[,other.json] [--name=left[,right]] --out_dir=DIR
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/world/planning_world.h"
#include "fit_result_file.h"

DEFINE_string(name, "",
              "world: the machines' instance names, in --result's order (comma list); default: "
              "each URDF's robot name. Every link and joint of a machine is prefixed '<name>_'.");

namespace edgefit::tools {
namespace {

using nlohmann::json;

int RunWorld(const Command& command) {
  const std::vector<std::string> results = SplitList(FLAGS_result);
  const std::vector<std::string> names = SplitList(FLAGS_name);
  if (results.empty()) return BadInput(command, "--result is required");
  if (FLAGS_out_dir.empty()) return BadInput(command, "--out_dir is required");
  if (!names.empty() && names.size() != results.size()) {
    return BadInput(command, "--name gives " + std::to_string(names.size()) + " names for " +
                                 std::to_string(results.size()) + " results");
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputFolder(FLAGS_out_dir));
  std::vector<KinematicModel> models(results.size());
  std::vector<WorldMachine> machines(results.size());
  std::vector<std::string> notes(results.size());
  for (size_t i = 0; i < results.size(); ++i) {
    std::string text;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadFileToString(results[i], &text));
    const json result = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (result.is_discarded()) return BadInput(command, results[i] + ": not JSON");
    WorldMachine& m = machines[i];
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, ReadFittedModel(result, results[i], &models[i], &m.q, &m.T_world_base));
    m.model = &models[i];
    m.name = names.empty() ? models[i].name() : names[i];
    m.source = results[i];
    const json& quality = result.value("quality", json::object());
    if (quality.is_object() && !quality.value("ok", true)) {
      notes[i] = " (the fit said not ok: " + quality.value("message", std::string()) +
                 "; placed as fitted)";
    }
  }
  std::vector<std::string> written;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, WritePlanningWorld(machines, FLAGS_out_dir, &written));
  for (size_t i = 0; i < machines.size(); ++i) {
    const WorldMachine& m = machines[i];
    std::printf("%s: %s, %zu links, prefixed %s_%s\n", m.name.c_str(), m.source.c_str(),
                m.model->links().size(), m.name.c_str(), notes[i].c_str());
  }
  std::printf("world: %s (%zu files: cell.urdf, cell_frozen.urdf, cell.srdf, joint_states.yaml, "
              "machines_as_scanned.ply, meshes/)\n",
              FLAGS_out_dir.c_str(), written.size());
  return 0;
}

}  // namespace

Command WorldCommand() {
  return {"world",
          "the fitted machines as a world that motion planners load: cell.urdf (root 'world', "
          "each machine at its fitted base), cell_frozen.urdf, cell.srdf (as_scanned), "
          "joint_states.yaml, machines_as_scanned.ply",
          "Usage:\n"
          "  edgefit world --result=R.json[,R2.json] [--name=N[,N2]] --out_dir=DIR\n"
          "Example:\n"
          "  edgefit fit --urdf=assets/robot/robot.urdf --scan=robot.ptx --out=result.json\n"
          "  edgefit world --result=result.json --name=robot --out_dir=world\n"
          "  check_urdf world/cell.urdf",
          {"result", "name", "out_dir"},
          RunWorld};
}

}  // namespace edgefit::tools
