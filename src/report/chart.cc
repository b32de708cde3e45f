#include "edgefit/report/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/format.h"
#include "html.h"

namespace edgefit {
namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                    "#9467bd", "#8c564b", "#e377c2", "#17becf"};


// An axis: data range to pixels, and where its ticks go.
struct Axis {
  double lo = 0.0, hi = 1.0;  // in data units (log10 of them on a log axis)
  bool log = false;
  double pixel_lo = 0.0, pixel_hi = 1.0;

  double Pixel(double value) const {
    double v = value;
    if (log) v = value > 0.0 ? std::log10(value) : lo;
    return pixel_lo + (v - lo) / (hi - lo) * (pixel_hi - pixel_lo);
  }
  // Tick values (data units) and their labels.
  std::vector<std::pair<double, std::string>> Ticks() const {
    std::vector<std::pair<double, std::string>> ticks;
    if (log) {
      for (int e = static_cast<int>(std::floor(lo)); e <= static_cast<int>(std::ceil(hi)); ++e) {
        for (const int m : {1, 2, 5}) {
          const double v = m * std::pow(10.0, e);
          const double l = std::log10(v);
          if (l < lo - 1e-9 || l > hi + 1e-9) continue;
          if (m != 1 && hi - lo > 3.0) continue;  // decades only over a wide range
          ticks.emplace_back(v, FormatNumber("%g", v));
        }
      }
      return ticks;
    }
    const double raw = (hi - lo) / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
      step = m * magnitude;
      if (step >= raw) break;
    }
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) {
      ticks.emplace_back(v, FormatNumber("%g", std::abs(v) < 1e-12 * step ? 0.0 : v));
    }
    return ticks;
  }
};

// The range of `values` (finite, positive on a log axis) with some room.
Axis MakeAxis(const std::vector<double>& values, bool log, bool pad) {
  Axis axis;
  axis.log = log;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double v : values) {
    if (!std::isfinite(v) || (log && v <= 0.0)) continue;
    const double d = log ? std::log10(v) : v;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
  if (log) {
    lo = std::floor(lo + 1e-9);
    hi = std::ceil(hi - 1e-9);
    if (hi <= lo) hi = lo + 1.0;
    axis.lo = lo;
    axis.hi = hi;
    return axis;
  }
  if (pad) {
    lo = std::min(lo, 0.0);  // errors: from zero
    hi = hi > lo ? hi * 1.08 : lo + 1.0;
  } else if (hi <= lo) {
    lo -= 0.5;
    hi += 0.5;
  } else {
    const double m = 0.05 * (hi - lo);
    lo -= m;
    hi += m;
  }
  axis.lo = lo;
  axis.hi = hi;
  return axis;
}

}  // namespace

std::string SvgChart(const Chart& chart, int width, int height) {
  const bool categorical = !chart.categories.empty();
  std::vector<double> xs, ys;
  for (const ChartSeries& s : chart.series) {
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    ys.insert(ys.end(), s.y.begin(), s.y.end());
  }
  const double left = 70, right = 16, top = 28, legend_height = 16.0 * chart.series.size();
  const double bottom = 46 + legend_height;
  Axis x_axis;
  if (categorical) {
    x_axis.lo = -0.5;
    x_axis.hi = static_cast<double>(chart.categories.size()) - 0.5;
  } else {
    x_axis = MakeAxis(xs, chart.log_x, false);
  }
  Axis y_axis = MakeAxis(ys, chart.log_y, true);
  x_axis.pixel_lo = left;
  x_axis.pixel_hi = width - right;
  y_axis.pixel_lo = height - bottom;
  y_axis.pixel_hi = top;

  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" width=\"" +
                    std::to_string(width) + "\" height=\"" + std::to_string(height) +
                    "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
                    "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<text x=\"" + FormatNumber("%.0f", left) + "\" y=\"16\" font-size=\"13\">" +
         EscapeHtml(chart.title) + "</text>\n";
  // Grid and ticks.
  for (const auto& [v, label] : y_axis.Ticks()) {
    const double py = y_axis.Pixel(v);
    svg += "<line x1=\"" + FormatNumber("%.1f", left) + "\" x2=\"" + FormatNumber("%.1f", width - right) +
           "\" y1=\"" + FormatNumber("%.1f", py) + "\" y2=\"" + FormatNumber("%.1f", py) +
           "\" stroke=\"#e5e5e5\"/>\n<text x=\"" + FormatNumber("%.1f", left - 4) + "\" y=\"" +
           FormatNumber("%.1f", py + 4) + "\" text-anchor=\"end\">" + EscapeHtml(label) + "</text>\n";
  }
  std::vector<std::pair<double, std::string>> x_ticks;
  if (categorical) {
    for (size_t k = 0; k < chart.categories.size(); ++k) {
      x_ticks.emplace_back(static_cast<double>(k), chart.categories[k]);
    }
  } else {
    // On a log x axis of few decades, ticks at the data's own values read best.
    x_ticks = x_axis.Ticks();
    if (chart.log_x) {
      std::vector<double> unique = xs;
      std::sort(unique.begin(), unique.end());
      unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
      if (unique.size() <= 10) {
        x_ticks.clear();
        for (const double v : unique) x_ticks.emplace_back(v, FormatNumber("%g", v));
      }
    }
  }
  const double axis_y = height - bottom;
  for (const auto& [v, label] : x_ticks) {
    const double px = x_axis.Pixel(v);
    svg += "<line x1=\"" + FormatNumber("%.1f", px) + "\" x2=\"" + FormatNumber("%.1f", px) + "\" y1=\"" +
           FormatNumber("%.1f", axis_y) + "\" y2=\"" + FormatNumber("%.1f", axis_y + 4) +
           "\" stroke=\"#444\"/>\n<text x=\"" + FormatNumber("%.1f", px) + "\" y=\"" +
           FormatNumber("%.1f", axis_y + 16) + "\" text-anchor=\"middle\">" + EscapeHtml(label) +
           "</text>\n";
  }
  svg += "<line x1=\"" + FormatNumber("%.1f", left) + "\" x2=\"" + FormatNumber("%.1f", width - right) +
         "\" y1=\"" + FormatNumber("%.1f", axis_y) + "\" y2=\"" + FormatNumber("%.1f", axis_y) +
         "\" stroke=\"#444\"/>\n<line x1=\"" + FormatNumber("%.1f", left) + "\" x2=\"" +
         FormatNumber("%.1f", left) + "\" y1=\"" + FormatNumber("%.1f", top) + "\" y2=\"" +
         FormatNumber("%.1f", axis_y) + "\" stroke=\"#444\"/>\n";
  svg += "<text x=\"" + FormatNumber("%.1f", 0.5 * (left + width - right)) + "\" y=\"" +
         FormatNumber("%.1f", axis_y + 32) + "\" text-anchor=\"middle\">" + EscapeHtml(chart.x_label) +
         "</text>\n";
  svg += "<text transform=\"translate(14," + FormatNumber("%.1f", 0.5 * (top + axis_y)) +
         ") rotate(-90)\" text-anchor=\"middle\">" + EscapeHtml(chart.y_label) + "</text>\n";
  // Series: polylines through the finite points (broken where one is not),
  // a marker on each.
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& series = chart.series[s];
    const std::string colour = kColours[s % (sizeof(kColours) / sizeof(kColours[0]))];
    const std::string stroke = "\" stroke=\"" + colour + "\" stroke-width=\"1.5\"" +
                               (series.dashed ? " stroke-dasharray=\"5,3\"" : "");
    std::string points;
    const auto end_line = [&] {
      if (series.line && !points.empty()) svg += "<polyline fill=\"none" + stroke + " points=\"" + points + "\"/>\n";
      points.clear();
    };
    std::string markers;
    for (size_t k = 0; k < series.x.size() && k < series.y.size(); ++k) {
      if (!std::isfinite(series.y[k]) || !std::isfinite(series.x[k])) {
        end_line();
        continue;
      }
      const double px = x_axis.Pixel(series.x[k]), py = y_axis.Pixel(series.y[k]);
      points += FormatNumber("%.1f", px) + "," + FormatNumber("%.1f", py) + " ";
      if (!series.markers) continue;
      markers += "<circle cx=\"" + FormatNumber("%.1f", px) + "\" cy=\"" + FormatNumber("%.1f", py) +
                 "\" r=\"3\" fill=\"" + colour + "\"><title>" + EscapeHtml(series.name) + ": " +
                 FormatNumber("%g", series.y[k]) + "</title></circle>\n";
    }
    end_line();
    svg += markers;
    const double ly = height - legend_height + 16.0 * s + 4;
    svg += "<line x1=\"" + FormatNumber("%.1f", left) + "\" x2=\"" + FormatNumber("%.1f", left + 22) +
           "\" y1=\"" + FormatNumber("%.1f", ly) + "\" y2=\"" + FormatNumber("%.1f", ly) + stroke +
           (series.line ? "" : " stroke-opacity=\"0\"") + "/>\n" +
           (series.line ? "" : "<circle cx=\"" + FormatNumber("%.1f", left + 11) + "\" cy=\"" +
                                   FormatNumber("%.1f", ly) + "\" r=\"3\" fill=\"" + colour + "\"/>\n") +
           "<text x=\"" + FormatNumber("%.1f", left + 28) + "\" y=\"" + FormatNumber("%.1f", ly + 4) +
           "\">" + EscapeHtml(series.name) + "</text>\n";
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace edgefit
