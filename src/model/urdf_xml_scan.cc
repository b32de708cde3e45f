#include "urdf_xml_scan.h"

#include <tinyxml2.h>

#include <map>
#include <sstream>
#include <utility>

namespace edgefit {
namespace {

bool ParseVector3(const char* text, Eigen::Vector3d* v) {
  if (text == nullptr) return false;
  std::istringstream in(text);
  std::string extra;
  return static_cast<bool>(in >> v->x() >> v->y() >> v->z()) && !(in >> extra);
}

// The link named by a joint's <parent> or <child> element ("" when absent:
// urdfdom reports that).
std::string JointLink(const tinyxml2::XMLElement* joint, const char* tag) {
  const tinyxml2::XMLElement* e = joint->FirstChildElement(tag);
  const char* link = e != nullptr ? e->Attribute("link") : nullptr;
  return link != nullptr ? link : "";
}

// The joints must form a tree: no link its own parent, none the child of two
// joints, no cycle. Checked before urdfdom, which leaks the links of a
// cycle and names no joint.
Status CheckTree(const std::vector<std::string>& joints,
                 const std::map<std::string, std::pair<std::string, std::string>>& parent_child) {
  std::map<std::string, std::string> joint_of_child;  // child link -> joint
  for (const std::string& joint : joints) {
    const auto& [parent, child] = parent_child.at(joint);
    if (parent.empty() || child.empty()) continue;
    if (parent == child) {
      return Status::Error("joint '" + joint + "': parent and child are the same link '" +
                           parent + "'");
    }
    const auto [it, fresh] = joint_of_child.emplace(child, joint);
    if (!fresh) {
      return Status::Error("link '" + child + "' is the child of two joints, '" + it->second +
                           "' and '" + joint + "'");
    }
  }
  for (const auto& [child, joint] : joint_of_child) {
    std::string link = child;
    for (size_t steps = 0;; ++steps) {
      const auto up = joint_of_child.find(link);
      if (up == joint_of_child.end()) break;
      link = parent_child.at(up->second).first;
      if (steps > joint_of_child.size()) {
        return Status::Error("joint '" + joint + "': the joints above it form a cycle");
      }
    }
  }
  return Status::Ok();
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
  std::map<std::string, std::pair<std::string, std::string>> parent_child;  // per joint
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
      if (parent_child.count(name) != 0) return Status::Error(where + ": defined twice");
      parent_child[name] = {JointLink(e, "parent"), JointLink(e, "child")};
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
  return CheckTree(scan->joint_names, parent_child);
}

}  // namespace edgefit
