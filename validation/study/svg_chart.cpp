#include "svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace drillflex::study {
namespace {

constexpr double kWidth = 720.0;
constexpr double kPanelHeight = 240.0;
constexpr double kLeft = 80.0, kRight = 210.0, kTop = 50.0, kGap = 40.0, kBottom = 60.0;
constexpr double kPlotWidth = kWidth - kLeft - kRight;

// Whole decades [10^lo, 10^hi] enclosing the positive values.
struct DecadeRange {
  int lo = 0, hi = 1;
  double Fraction(double value) const { return (std::log10(value) - lo) / (hi - lo); }
};

DecadeRange RangeOf(const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values) {
    if (v > 0.0) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi)) return {};
  DecadeRange range{static_cast<int>(std::floor(std::log10(lo) + 1e-9)),
                    static_cast<int>(std::ceil(std::log10(hi) - 1e-9))};
  if (range.hi == range.lo) ++range.hi;
  return range;
}

// "10" with the exponent raised.
std::string DecadeLabel(int exponent, double x, double y, const char* anchor) {
  return fmt::format(R"svg(<text x="{:.1f}" y="{:.1f}" text-anchor="{}">10<tspan dy="-6" font-size="9">{}</tspan></text>)svg",
                     x, y, anchor, exponent) + "\n";
}

std::string Axes(const DecadeRange& xr, const DecadeRange& yr, double top, bool x_labels) {
  std::string svg;
  const double bottom = top + kPanelHeight;
  for (int e = xr.lo; e <= xr.hi; ++e) {
    const double x = kLeft + xr.Fraction(std::pow(10.0, e)) * kPlotWidth;
    svg += fmt::format(R"svg(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#ddd"/>)svg", x, top, bottom) + "\n";
    if (x_labels) svg += DecadeLabel(e, x, bottom + 20.0, "middle");
  }
  for (int e = yr.lo; e <= yr.hi; ++e) {
    const double y = bottom - yr.Fraction(std::pow(10.0, e)) * kPanelHeight;
    svg += fmt::format(R"svg(<line x1="{0:.1f}" y1="{2:.1f}" x2="{1:.1f}" y2="{2:.1f}" stroke="#ddd"/>)svg", kLeft,
                       kLeft + kPlotWidth, y) + "\n";
    svg += DecadeLabel(e, kLeft - 8.0, y + 4.0, "end");
  }
  svg += fmt::format(R"svg(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333"/>)svg", kLeft, top,
                     kPlotWidth, kPanelHeight) + "\n";
  return svg;
}

// The dash attribute of a reference line (none for a data series).
const char* Dashes(const ChartSeries& series) { return series.reference ? R"svg( stroke-dasharray="8,5")svg" : ""; }

std::string SeriesPath(const ChartSeries& series, const DecadeRange& xr, const DecadeRange& yr, double top) {
  std::string points, markers;
  for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
    if (series.x[i] <= 0.0 || series.y[i] <= 0.0) continue;
    const double x = kLeft + xr.Fraction(series.x[i]) * kPlotWidth;
    const double y = top + kPanelHeight - yr.Fraction(series.y[i]) * kPanelHeight;
    points += fmt::format("{:.1f},{:.1f} ", x, y);
    if (!series.reference) markers += fmt::format(R"svg(<circle cx="{:.1f}" cy="{:.1f}" r="3" fill="{}"/>)svg", x, y, series.color) + "\n";
  }
  std::string svg = fmt::format(R"svg(<polyline points="{}" fill="none" stroke="{}" stroke-width="2"{}/>)svg", points,
                                series.color, Dashes(series));
  return svg.append("\n").append(markers);
}

std::string Panel(const ChartPanel& panel, const DecadeRange& xr, double top, bool x_labels) {
  std::vector<double> ys;
  for (const ChartSeries& s : panel.series) ys.insert(ys.end(), s.y.begin(), s.y.end());
  const DecadeRange yr = RangeOf(ys);
  std::string svg = Axes(xr, yr, top, x_labels);
  const double middle = top + kPanelHeight / 2.0;
  svg += fmt::format(R"svg(<text x="18" y="{0:.1f}" transform="rotate(-90 18 {0:.1f})" text-anchor="middle">{1}</text>)svg",
                     middle, panel.y_label) + "\n";
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const ChartSeries& s = panel.series[i];
    svg += SeriesPath(s, xr, yr, top);
    const double legend_y = top + 16.0 + 20.0 * static_cast<double>(i);
    const double legend_x = kLeft + kPlotWidth + 14.0;
    svg += fmt::format(R"svg(<line x1="{0:.1f}" y1="{2:.1f}" x2="{1:.1f}" y2="{2:.1f}" stroke="{3}" stroke-width="2"{4}/>)svg",
                       legend_x, legend_x + 22.0, legend_y - 4.0, s.color, Dashes(s)) + "\n";
    svg += fmt::format(R"svg(<text x="{:.1f}" y="{:.1f}">{}</text>)svg", legend_x + 28.0, legend_y, s.name) + "\n";
  }
  return svg;
}

}  // namespace

std::string RenderSvg(const Chart& chart) {
  std::vector<double> xs;
  for (const ChartPanel& p : chart.panels) {
    for (const ChartSeries& s : p.series) xs.insert(xs.end(), s.x.begin(), s.x.end());
  }
  const DecadeRange xr = RangeOf(xs);
  const double panels = static_cast<double>(chart.panels.size());
  const double height = kTop + panels * kPanelHeight + (panels - 1.0) * kGap + kBottom;
  std::string svg = fmt::format(
      R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" )svg"
      R"svg(font-family="sans-serif" font-size="12">)svg" "\n"
      R"svg(<rect width="100%" height="100%" fill="white"/>)svg" "\n"
      R"svg(<text x="{2:.1f}" y="28" text-anchor="middle" font-size="15">{3}</text>)svg" "\n",
      kWidth, height, kLeft + kPlotWidth / 2.0, chart.title);
  for (std::size_t i = 0; i < chart.panels.size(); ++i) {
    const double top = kTop + static_cast<double>(i) * (kPanelHeight + kGap);
    svg += Panel(chart.panels[i], xr, top, i + 1 == chart.panels.size());
  }
  const double bottom = height - kBottom;
  for (const ChartMarker& marker : chart.markers) {
    const double x = kLeft + xr.Fraction(marker.x) * kPlotWidth;
    svg += fmt::format(R"svg(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#555" stroke-dasharray="5,4"/>)svg",
                       x, kTop, bottom) + "\n";
    svg += fmt::format(R"svg(<text x="{:.1f}" y="{:.1f}" font-size="11" fill="#555">{}</text>)svg", x + 4.0, kTop + 12.0,
                       marker.label) + "\n";
  }
  svg += fmt::format(R"svg(<text x="{:.1f}" y="{:.1f}" text-anchor="middle">{}</text>)svg", kLeft + kPlotWidth / 2.0,
                     height - 15.0, chart.x_label) + "\n";
  svg += "</svg>\n";
  return svg;
}

}  // namespace drillflex::study
