#include "urdf_xml_scan.h"

#include <tinyxml2.h>

#include <sstream>

namespace edgefit {
namespace {

bool ParseVector3(const char* text, Eigen::Vector3d* v) {
  if (text == nullptr) return false;
  std::istringstream in(text);
  std::string extra;
  return static_cast<bool>(in >> v->x() >> v->y() >> v->z()) && !(in >> extra);
}

}  // namespace

Status ScanUrdfXml(const std::string& xml, UrdfXmlScan* scan) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    return Status::Error(std::string("XML error at line ") + std::to_string(doc.ErrorLineNum()) +
                         ": " + doc.ErrorName());
  }
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) return Status::Error("no <robot> element");
  for (const tinyxml2::XMLElement* e = robot->FirstChildElement(); e != nullptr;
       e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    const char* name = e->Attribute("name");
    if (tag == "link" && name != nullptr) scan->link_names.push_back(name);
    if (tag == "joint") {
      if (name == nullptr) return Status::Error("<joint> without a name");
      const char* type = e->Attribute("type");
      const std::string where = std::string("joint '") + name + "'";
      if (type == nullptr) return Status::Error(where + ": no type");
      const std::string t = type;
      if (t != "fixed" && t != "revolute" && t != "continuous" && t != "prismatic") {
        return Status::Error(where + ": unsupported type '" + t +
                             "' (edgefit handles fixed, revolute, continuous, prismatic)");
      }
      scan->joint_names.push_back(name);
    }
    if (tag == "loop_closure") {
      LoopClosureSpec spec;
      spec.name = name != nullptr ? name : "";
      const std::string where = "loop_closure '" + spec.name + "'";
      const char* link_a = e->Attribute("link_a");
      const char* link_b = e->Attribute("link_b");
      const char* joints = e->Attribute("joints");
      if (name == nullptr || link_a == nullptr || link_b == nullptr || joints == nullptr) {
        return Status::Error(where + ": needs name, link_a, link_b and joints");
      }
      spec.link_a = link_a;
      spec.link_b = link_b;
      if (!ParseVector3(e->Attribute("point_a"), &spec.p_link_a) ||
          !ParseVector3(e->Attribute("point_b"), &spec.p_link_b)) {
        return Status::Error(where + ": point_a and point_b must be \"x y z\" [m]");
      }
      std::istringstream in(joints);
      for (std::string j; in >> j;) spec.joints.push_back(j);
      scan->loop_closures.push_back(spec);
    }
  }
  return Status::Ok();
}

}  // namespace edgefit
