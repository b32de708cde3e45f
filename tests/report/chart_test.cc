#include "edgefit/report/chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace edgefit {
namespace {

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ChartTest, LogAxesTickDecadesAndTheDataValues) {
  Chart chart;
  chart.title = "revolute joints: mean error against w_high (Eq. 6)";
  chart.x_label = "w_high";
  chart.y_label = "mean error [deg]";
  chart.log_x = chart.log_y = true;
  chart.series = {{"robot, edge weights", {1, 10, 100}, {0.5, 0.02, 0.004}, false}};
  const std::string svg = SvgChart(chart);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  // y from 0.001 to 1: the decades; x: the values of w_high.
  for (const char* tick : {">0.001<", ">0.01<", ">0.1<", ">1<", ">10<", ">100<"}) {
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  }
  EXPECT_EQ(Count(svg, "<circle"), 3u);
  EXPECT_NE(svg.find("robot, edge weights"), std::string::npos);
}

TEST(ChartTest, AMissingValueLeavesAGapAndCategoriesAreLabels) {
  Chart chart;
  chart.categories = {"trivial", "huber", "<cauchy>"};
  chart.series = {{"conveyor", {0, 1, 2}, {0.1, std::nan(""), 0.3}, false},
                  {"robot", {0, 1, 2}, {0.2, 0.2, 0.2}, true}};
  const std::string svg = SvgChart(chart);
  EXPECT_EQ(Count(svg, "<circle"), 5u);
  EXPECT_NE(svg.find(">huber<"), std::string::npos);
  EXPECT_NE(svg.find("&lt;cauchy&gt;"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
  EXPECT_EQ(Count(svg, "<polyline"), 3u);  // the conveyor's line broken at its gap
}

TEST(ChartTest, MarkersOnlyOrLineOnly) {
  Chart chart;
  chart.series = {{"distance", {1, 2, 3, 4}, {5, 6, 7, 8}, false},
                  {"collision", {1, 2, 3, 4}, {std::nan(""), 0, 0, std::nan("")}, false}};
  chart.series[0].markers = false;
  chart.series[1].line = false;
  const std::string svg = SvgChart(chart);
  EXPECT_EQ(Count(svg, "<polyline"), 1u);
  EXPECT_EQ(Count(svg, "<circle"), 3u);  // two collisions and the legend's marker
  EXPECT_NE(svg.find("viewBox=\"0 0 600 360\""), std::string::npos);  // scales with CSS
}

}  // namespace
}  // namespace edgefit
