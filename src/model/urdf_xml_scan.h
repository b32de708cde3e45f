// Internal to the URDF loader: what edgefit reads from the URDF XML itself
// (tinyxml2) before urdfdom parses it.
#ifndef EDGEFIT_SRC_MODEL_URDF_XML_SCAN_H_
#define EDGEFIT_SRC_MODEL_URDF_XML_SCAN_H_

#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/loop_closure.h"

namespace edgefit {

// What we read from the XML ourselves before urdfdom sees it: element order
// (urdfdom keeps links and joints in name-sorted maps), joint types (so an
// unsupported type gets our message, not urdfdom's) and <loop_closure>s.
struct UrdfXmlScan {
  std::vector<std::string> link_names, joint_names;
  std::vector<LoopClosureSpec> loop_closures;
};

// Reads element order, joint types (unsupported types are an error naming
// the joint) and <loop_closure> elements from the URDF text `xml`, and
// checks that the joints form a tree (no link its own parent or the child
// of two joints, no cycle; an error naming the joint or link).
Status ScanUrdfXml(const std::string& xml, UrdfXmlScan* scan);

}  // namespace edgefit

#endif  // EDGEFIT_SRC_MODEL_URDF_XML_SCAN_H_
