// edgefit clearance: one machine of a planning world (edgefit world) against
// the background, the other machines and itself, posture by posture
// (include/edgefit/world/clearance.h says what is measured).
//   edgefit clearance --world=DIR [--machine=NAME] [--trajectory=traj.csv | --joints=...]
//                     [--step_deg=0.5] [--step_mm=5] [--json] [--out_report=R.html]
#include <gflags/gflags.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/format.h"
#include "edgefit/io/trajectory_csv.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/report/world_report.h"
#include "edgefit/world/clearance.h"

DEFINE_string(world, "", "clearance: the folder edgefit world wrote.");
DEFINE_string(machine, "",
              "clearance: the machine checked, by its instance name in the world (default: the "
              "world's only machine).");
DEFINE_string(trajectory, "",
              "clearance: a CSV trajectory: a header of the machine's joint names (as in its own "
              "URDF), then one row per waypoint [rad] or [m]; joints not named stay as scanned.");
DEFINE_double(step_deg, 0.5,
              "clearance: the way between waypoints is checked at states no revolute joint "
              "moves more than this apart [deg].");
DEFINE_double(step_mm, 5.0,
              "clearance: the same for prismatic joints [mm].");

namespace edgefit::tools {
namespace {

using nlohmann::json;

json Metres(double d) { return std::isfinite(d) ? json(d) : json(nullptr); }

std::string Millimetres(double d) {
  return std::isfinite(d) ? FormatNumber("%.1f", 1e3 * d) : std::string("-");
}

int RunClearance(const Command& command) {
  if (FLAGS_world.empty()) return BadInput(command, "--world is required (a folder of edgefit world)");
  if (!FLAGS_trajectory.empty() && !FLAGS_joints.empty()) {
    return BadInput(command, "give --trajectory or --joints, not both");
  }
  ClearanceOptions options;
  options.step_rad = FLAGS_step_deg * M_PI / 180.0;
  options.step_m = FLAGS_step_mm * 1e-3;
  if (std::string error; !options.IsValid(&error)) {
    return BadInput(command, "--step_deg and --step_mm must be > 0");
  }
  if (!FLAGS_out_report.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputPaths({FLAGS_out_report}));
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckThreeJs(WorldReport().three_js_dir));
  }
  Progress("clearance: loading " + FLAGS_world);
  ClearanceWorld world;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, world.Load(FLAGS_world, FLAGS_machine, options.max_distance));
  const std::string& machine = world.machine();

  // The waypoints: the trajectory's rows, or one posture.
  std::vector<std::vector<double>> waypoints;
  if (!FLAGS_trajectory.empty()) {
    Trajectory trajectory;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadTrajectoryCsv(FLAGS_trajectory, &trajectory));
    for (size_t k = 0; k < trajectory.waypoints.size(); ++k) {
      std::vector<std::pair<std::string, double>> values;
      for (size_t j = 0; j < trajectory.joints.size(); ++j) {
        values.emplace_back(trajectory.joints[j], trajectory.waypoints[k][j]);
      }
      waypoints.emplace_back();
      if (Status s = world.Posture(values, &waypoints.back()); !s.ok()) {
        return BadInput(command, FLAGS_trajectory + ": waypoint " + std::to_string(k + 1) + ": " +
                                     s.message());
      }
    }
  } else {
    std::vector<std::pair<std::string, double>> values;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseNamedValues(FLAGS_joints, &values));
    waypoints.emplace_back();
    if (Status s = world.Posture(values, &waypoints.back()); !s.ok()) {
      return BadInput(command, "--joints: " + s.message());
    }
  }
  Progress("clearance: " + machine + ", " + std::to_string(waypoints.size()) + " waypoint(s)");
  Status status;
  const std::vector<PostureClearance> results = world.Check(waypoints, options, &status);
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, status);

  int first = -1;
  for (size_t k = 0; k < results.size() && first < 0; ++k) {
    if (results[k].colliding) first = static_cast<int>(k);
  }
  if (!FLAGS_out_report.empty()) {
    Progress("clearance: the report");
    WorldReport report;
    report.title = "edgefit clearance: " + machine + " in " + FLAGS_world;
    report.lines = {
        (!FLAGS_trajectory.empty() ? "--trajectory=" + FLAGS_trajectory
         : FLAGS_joints.empty()    ? std::string("as scanned")
                                   : "--joints=" + FLAGS_joints) +
            ": " + std::to_string(results.size()) + " waypoint(s), the way between checked every " +
            FormatNumber("%.2f deg / ", FLAGS_step_deg) + FormatNumber("%.1f mm", FLAGS_step_mm),
        first < 0 ? std::string("no collision")
                  : "first collision: waypoint " + std::to_string(first + 1) + ", " +
                        DescribeCollision(results[static_cast<size_t>(first)])};
    EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                                 world.Picture(waypoints, results, ClearancePictureOptions(), &report));
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, WriteWorldReport(report, FLAGS_out_report));
  }
  if (FLAGS_json) {
    json out = {{"world", FLAGS_world},
                {"machine", machine},
                {"step_rad", options.step_rad},
                {"step_m", options.step_m},
                {"first_collision", first < 0 ? json(nullptr) : json(first)},
                {"waypoints", json::array()}};
    for (const PostureClearance& c : results) {
      json w = {{"distance_to_background", Metres(c.distance_to_background)},
                {"distance_to_machines", Metres(c.distance_to_machines)},
                {"self_distance", Metres(c.self_distance)},
                {"colliding", c.colliding}};
      if (c.colliding) {
        w["pair"] = {c.collision_a, c.collision_b};
        w["collision_fraction"] = c.collision_fraction;
        w["point"] = {c.p_world_collision.x(), c.p_world_collision.y(), c.p_world_collision.z()};
      }
      out["waypoints"].push_back(w);
    }
    if (!FLAGS_out_report.empty()) out["report"] = FLAGS_out_report;
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  std::printf("%s in %s: %zu waypoint(s), the way between checked every %.2f deg / %.1f mm\n",
              machine.c_str(), FLAGS_world.c_str(), results.size(), FLAGS_step_deg, FLAGS_step_mm);
  std::printf("%8s  %14s  %14s  %10s  %s\n", "waypoint", "background[mm]", "machines[mm]",
              "self[mm]", "collision");
  for (size_t k = 0; k < results.size(); ++k) {
    const PostureClearance& c = results[k];
    const std::string collision = c.colliding ? DescribeCollision(c) : "-";
    std::printf("%8zu  %14s  %14s  %10s  %s\n", k + 1, Millimetres(c.distance_to_background).c_str(),
                Millimetres(c.distance_to_machines).c_str(), Millimetres(c.self_distance).c_str(),
                collision.c_str());
  }
  if (first < 0) {
    std::printf("no collision\n");
  } else {
    std::printf("first collision: waypoint %d\n", first + 1);
  }
  if (!FLAGS_out_report.empty()) std::printf("report: %s\n", FLAGS_out_report.c_str());
  return 0;
}

}  // namespace

Command ClearanceCommand() {
  return {"clearance",
          "one machine of a planning world (edgefit world) posed by --joints or along "
          "--trajectory: its distance to the background, to the other machines and between its "
          "own links, and the first collision (FCL)",
          "Usage:\n"
          "  edgefit clearance --world=DIR [--machine=NAME] [--trajectory=traj.csv | --joints=a1=0.3,...]\n"
          "                    [--step_deg=0.5] [--step_mm=5] [--json] [--out_report=R.html]\n"
          "Example:\n"
          "  edgefit world --result=result.json --name=robot --out_dir=world\n"
          "  edgefit clearance --world=world --joints=joint_2=-30deg\n"
          "Waypoints are numbered from 1 in the text (rows after the header) and from 0 in\n"
          "--json; a collision on the way from waypoint k-1 to k is reported on k.\n"
          "--out_report: an HTML page of the world (the background near the way, every machine\n"
          "with its attachments), the machine at each waypoint on a slider, where it collides,\n"
          "and the clearance along the trajectory as a plot.",
          {"world", "machine", "trajectory", "joints", "step_deg", "step_mm", "json", "out_report"},
          RunClearance};
}

}  // namespace edgefit::tools
