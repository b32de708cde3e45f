// A line chart drawn as SVG (inline in the reports, no script needed): the
// bench's ablation plots, error against w_high, lambda, loss, spacing, ...
#ifndef EDGEFIT_REPORT_CHART_H_
#define EDGEFIT_REPORT_CHART_H_

#include <string>
#include <vector>

namespace edgefit {

struct ChartSeries {
  std::string name;
  std::vector<double> x, y;  // same length; a non-finite y leaves a gap
  bool dashed = false;
  bool line = true;     // a line through the points (broken at gaps)
  bool markers = true;  // a marker on each point (hover: its value)
};

struct Chart {
  std::string title, x_label, y_label;
  // Non-empty: the x axis is categorical and x are indices into these.
  std::vector<std::string> categories;
  bool log_x = false, log_y = false;  // log axes need positive values
  std::vector<ChartSeries> series;
};

// The chart as an <svg> element of width x height pixels: axes with ticks
// (decades on log axes), a polyline with markers per series, a legend.
// Values a log axis cannot show (<= 0) are drawn at its lower end.
std::string SvgChart(const Chart& chart, int width = 600, int height = 360);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_CHART_H_
