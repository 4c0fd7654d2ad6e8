// A small hand-written SVG chart: panels stacked over one shared logarithmic x axis, each with a
// logarithmic y axis, lines with point markers, a legend, and optional vertical marker lines.
#pragma once

#include <string>
#include <vector>

namespace drillflex::study {

struct ChartSeries {
  std::string name;
  std::string color;      // any SVG colour, e.g. "#1f77b4"
  std::vector<double> x;  // > 0
  std::vector<double> y;  // points with y ≤ 0 are left out (no place on a log axis)
  bool reference = false;  // a dashed reference line without point markers
};

struct ChartPanel {
  std::string y_label;
  std::vector<ChartSeries> series;
};

struct ChartMarker {
  double x = 0.0;
  std::string label;
};

struct Chart {
  std::string title;
  std::string x_label;
  std::vector<ChartPanel> panels;
  std::vector<ChartMarker> markers;  // vertical lines through every panel
};

// The chart as a standalone SVG document.
std::string RenderSvg(const Chart& chart);

}  // namespace drillflex::study
