#include "edgefit/scanner/edge_metrics.h"

#include <glog/logging.h>

#include <cstdio>

#include "edgefit/scene/scene.h"

namespace edgefit {
namespace {

double Ratio(size_t a, size_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / b; }

}  // namespace

double EdgeMetrics::precision() const { return Ratio(true_positives, link_high); }
double EdgeMetrics::recall() const { return Ratio(true_positives, true_edges); }
double EdgeMetrics::accessory_share() const { return Ratio(accessory_high, accessory_points); }
double EdgeMetrics::accessory_share_of_high() const {
  return Ratio(accessory_high, accessory_high + link_high);
}

std::string EdgeMetrics::BriefReport() const {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer),
                "precision %.3f, recall %.3f (%zu true edges of %zu link points), "
                "accessory share %.3f (%zu of %zu)",
                precision(), recall(), true_edges, link_points, accessory_share(),
                accessory_high, accessory_points);
  return buffer;
}

EdgeMetrics EvaluateEdgeWeights(const std::vector<std::vector<uint16_t>>& labels,
                                const std::vector<std::vector<float>>& w_edge) {
  CHECK_EQ(labels.size(), w_edge.size());
  EdgeMetrics m;
  for (size_t s = 0; s < labels.size(); ++s) {
    CHECK_EQ(labels[s].size(), w_edge[s].size()) << "scan " << s;
    for (size_t i = 0; i < labels[s].size(); ++i) {
      const uint16_t label = labels[s][i] & kLabelMask;
      const bool high = w_edge[s][i] > 1.0f;
      if (IsLinkLabel(label)) {
        const bool truth = (labels[s][i] & kTrueEdgeFlag) != 0;
        ++m.link_points;
        m.true_edges += truth;
        m.link_high += high;
        m.true_positives += truth && high;
      } else if (label == kLabelAccessory) {
        ++m.accessory_points;
        m.accessory_high += high;
      } else if (label == kLabelBackground) {
        ++m.background_points;
        m.background_high += high;
      }
    }
  }
  return m;
}

}  // namespace edgefit
