// Malformed input to `edgefit fit`, one table: truncated files, wrong
// counts, NaN and Inf, huge or negative sizes, wrong field types, missing
// meshes, cyclic URDFs, mimic loops, units where numbers belong, a URDF in
// millimetres. Each ends with exit 2, one stderr line naming the file and
// the problem, nothing on stdout, and none of the requested outputs left
// behind.
#include <string>
#include <vector>

#include "tools/cli_fixture.h"

namespace edgefit_cli_test {
namespace {

const std::string kAssets = std::string(EDGEFIT_SOURCE_DIR) + "/assets/";

struct BadFile {
  const char* name;       // the test case, and the file's name before its extension
  const char* extension;  // "urdf": the model is bad; else the scan
  std::string content;
  std::string expected;  // in the one stderr line, beside the file's path
};

std::string Robot(const std::string& links_and_joints) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n" + links_and_joints + "\n</robot>\n";
}

std::string BoxLink(const std::string& name, const std::string& size = "0.1 0.1 0.1") {
  return "<link name=\"" + name + "\"><visual><geometry><box size=\"" + size +
         "\"/></geometry></visual></link>";
}

std::string Joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& extra = "") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/><axis xyz=\"0 0 1\"/>" +
         (type == "revolute" || type == "prismatic"
              ? "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
              : "") +
         extra + "</joint>";
}

std::vector<BadFile> Cases() {
  const std::string ptx_header =
      "3\n3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  std::string ptx_points;
  for (int i = 0; i < 9; ++i) {
    ptx_points +=
        "1 " + std::to_string(0.1 * (i / 3)) + " " + std::to_string(0.1 * (i % 3)) + " 0.5\n";
  }
  const std::string pcd_header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
      "POINTS 2\n";
  const std::string ply_header =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  const std::string two = BoxLink("a") + BoxLink("b");
  return {
      // Scans.
      {"PtxEmpty", "ptx", "", "no scans"},
      {"PtxTruncatedHeader", "ptx", "3\n3\n0 0 0\n1 0 0\n", "file ends inside a scan header"},
      {"PtxTruncatedPoints", "ptx", ptx_header + ptx_points.substr(0, 30),
       "header promises 3 x 3 points but only 30 bytes follow"},
      {"PtxNegativeRows", "ptx", "-3\n3\n" + ptx_header.substr(4) + ptx_points,
       "expected a positive integer"},
      {"PtxHugeSize", "ptx", "2000000000\n2000000000\n" + ptx_header.substr(4), "header promises"},
      {"PtxNanPoint", "ptx", ptx_header + "nan 0 0 0.5\n" + ptx_points.substr(10),
       "non-finite coordinate"},
      {"PtxInfMatrix", "ptx", "3\n3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\ninf 0 0 0\n", "non-finite"},
      {"PtxWordForNumber", "ptx", ptx_header + "1 0 zero 0.5\n" + ptx_points.substr(8),
       "line 11: expected 4 numbers"},
      {"PtxUnitsAfterNumbers", "ptx", "3\n3\n0 0 0 m\n", "line 3"},
      {"PtxNotRigid", "ptx",
       "3\n3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n", "not a rigid"},
      {"PcdWrongCount", "pcd",
       "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 3\nDATA ascii\n",
       "POINTS 3 != WIDTH x HEIGHT 2"},
      {"PcdWrongFieldType", "pcd",
       "FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2 3\n",
       "unsupported TYPE/SIZE"},
      {"PcdTruncatedBinary", "pcd", pcd_header + "DATA binary\n" + std::string(20, '\0'),
       "file truncated"},
      {"PcdInf", "pcd", pcd_header + "DATA ascii\n1 2 3\n1 inf 3\n", "infinite coordinate"},
      {"PcdNoData", "pcd", pcd_header, "no DATA line"},
      {"E57Empty", "e57", "", "empty file"},
      {"E57NotE57", "e57", std::string(2048, 'x'),
       "page 0 (bytes 0-1023) fails its CRC-32C checksum"},
      {"E57Truncated", "e57", std::string(1000, '\0'), "not a whole number of 1024-byte E57 pages"},
      {"PlyNotPly", "ply", "solid cube\n", "not a PLY file"},
      {"PlyTruncated", "ply", ply_header + "1 2 3\n", "file ends after 1 of 2"},
      {"PlyNan", "ply", ply_header + "1 2 3\nnan 2 3\n", "non-finite"},
      {"PlyPointList", "ply", ply_header + "1 2 3\n1 2 4\n",
       "the fit needs an organized scan on its angular lattice"},
      {"PlyNegativeCount", "ply",
       "ply\nformat ascii 1.0\nelement vertex -2\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n",
       "line 3: expected 'element <name> <count>' with 0 <= count"},
      {"UnknownFormat", "las", "LASF", "unknown scan format"},
      // Models.
      {"UrdfEmpty", "urdf", "", "XML_ERROR_EMPTY_DOCUMENT"},
      {"UrdfTruncated", "urdf", Robot(two).substr(0, 60), "XML error at line"},
      {"UrdfNotXml", "urdf", "robot: r\nlinks: [a]\n", "XML error at line 1"},
      {"UrdfNoLinks", "urdf", Robot(""), "No link elements found"},
      {"UrdfMissingMesh", "urdf",
       Robot("<link name=\"a\"><visual><geometry><mesh filename=\"meshes/gone.stl\"/>"
             "</geometry></visual></link>"),
       "gone.stl"},
      {"UrdfCyclic", "urdf",
       Robot(two + Joint("ab", "revolute", "a", "b") + Joint("ba", "revolute", "b", "a")),
       "the joints above it form a cycle"},
      {"UrdfLinkItsOwnParent", "urdf", Robot(two + Joint("bb", "revolute", "b", "b")),
       "joint 'bb': parent and child are the same link 'b'"},
      {"UrdfLinkWithTwoParents", "urdf",
       Robot(two + BoxLink("c") + Joint("ab", "fixed", "a", "b") + Joint("cb", "fixed", "c", "b")),
       "link 'b' is the child of two joints, 'ab' and 'cb'"},
      {"UrdfTwoRoots", "urdf", Robot(two + BoxLink("c") + Joint("ab", "revolute", "a", "b")),
       "Two root links found"},
      {"UrdfUnknownJointType", "urdf", Robot(two + Joint("ab", "spherical", "a", "b")),
       "spherical"},
      {"UrdfJointToMissingLink", "urdf", Robot(BoxLink("a") + Joint("ab", "revolute", "a", "b")),
       "child link [b] of joint [ab] not found"},
      {"UrdfMimicLoop", "urdf",
       Robot(two + BoxLink("c") +
             Joint("ab", "revolute", "a", "b", "<mimic joint=\"bc\" multiplier=\"1\"/>") +
             Joint("bc", "revolute", "b", "c", "<mimic joint=\"ab\" multiplier=\"1\"/>")),
       "mimic joints form a cycle"},
      {"UrdfMimicOfMissingJoint", "urdf",
       Robot(two + Joint("ab", "revolute", "a", "b", "<mimic joint=\"nope\"/>")), "nope"},
      {"UrdfNanOrigin", "urdf",
       Robot(two + Joint("ab", "revolute", "a", "b", "<origin xyz=\"0 nan 0\"/>")),
       "Unable to parse component [nan]"},
      {"UrdfUnitsInOrigin", "urdf",
       Robot(two + Joint("ab", "revolute", "a", "b", "<origin xyz=\"100mm 0 0\"/>")),
       "Unable to parse component [100mm]"},
      {"UrdfNegativeBox", "urdf", Robot(BoxLink("a", "0.1 -0.1 0.1")),
       "link 'a': box size must be three finite lengths > 0"},
      {"UrdfInfBox", "urdf", Robot(BoxLink("a", "0.1 inf 0.1")), "Unable to parse component [inf]"},
      {"UrdfInMillimetres", "urdf", Robot(BoxLink("a", "400 400 900")),
       "spans 900 m at its zero posture (more than 100 m): URDF lengths are metres"},
      {"UrdfZeroRadius", "urdf",
       Robot("<link name=\"a\"><visual><geometry><cylinder radius=\"0\" length=\"1\"/>"
             "</geometry></visual></link>"),
       "cylinder radius and length must be finite and > 0"},
      {"UrdfZeroMeshScale", "urdf",
       Robot("<link name=\"a\"><visual><geometry><mesh filename=\"" + kAssets +
             "robot/meshes/base_link.stl\" scale=\"0.001 0 0.001\"/></geometry></visual></link>"),
       "scale must be finite and non-zero"},
      {"UrdfZeroAxis", "urdf",
       Robot(two + "<joint name=\"ab\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
                   "<axis xyz=\"0 0 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
                   "velocity=\"1\"/></joint>"),
       "joint 'ab': zero axis"},
      {"UrdfLimitsReversed", "urdf",
       Robot(two + "<joint name=\"ab\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
                   "<axis xyz=\"0 0 1\"/><limit lower=\"1\" upper=\"-1\" effort=\"1\" "
                   "velocity=\"1\"/></joint>"),
       "joint 'ab': lower limit above upper limit"},
  };
}

class BadInputCliTest : public CliTest, public ::testing::WithParamInterface<BadFile> {};

TEST_P(BadInputCliTest, ExitsTwoWithOneLineAndNoOutput) {
  const BadFile& c = GetParam();
  const std::string bad = Write(std::string(c.name) + "." + c.extension, c.content);
  const bool model = std::string(c.extension) == "urdf";
  const std::string urdf = model ? bad : kAssets + "robot/robot.urdf";
  const std::string scan = model ? kAssets + "samples/two_scans.ptx" : bad;
  const std::string outputs = " --out=" + Path("result.json") +
                              " --out_joint_states=" + Path("j.yaml") +
                              " --out_urdf=" + Path("fitted.urdf");
  const RunResult r = Run("fit --urdf=" + urdf + " --scan=" + scan + outputs);
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(bad), std::string::npos) << "the file is not named: " << r.err;
  EXPECT_NE(r.err.find(c.expected), std::string::npos)
      << "expected '" << c.expected << "' in: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  for (const char* output : {"result.json", "j.yaml", "fitted.urdf"}) {
    EXPECT_FALSE(fs::exists(Path(output))) << output;
  }
}

INSTANTIATE_TEST_SUITE_P(Files, BadInputCliTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace edgefit_cli_test
