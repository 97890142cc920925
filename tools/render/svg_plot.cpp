#include "tools/render/svg_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "base/input_error.h"
#include "tools/io/atomic_file.h"

namespace scallop {

namespace {

// Margins of the plot area inside the picture, px.
constexpr double kLeft = 78, kRight = 24, kTop = 44, kBottom = 58;

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Tick label without trailing zeros beyond the tick step's precision.
std::string tickLabel(double v, double step) {
  const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
  if (std::fabs(v) < 0.5 * step) v = 0;  // no "-0"
  return fmt::format("{:.{}f}", v, decimals);
}

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int count) {
  std::vector<double> ticks;
  if (!(hi > lo) || count < 1) return ticks;
  const double raw = (hi - lo) / count;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = p;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * p;
    if (step >= raw) break;
  }
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(t);
  return ticks;
}

void SvgPlot::setRange(double xMin, double xMax, double yMin, double yMax) {
  xMin_ = xMin, xMax_ = xMax, yMin_ = yMin, yMax_ = yMax;
}

void SvgPlot::addLine(const std::vector<double>& x, const std::vector<double>& y,
                      const std::string& colour, const std::string& label, double widthPx,
                      const std::string& dash) {
  items_.push_back({Item::Line, x, y, colour, label, dash, widthPx});
}

void SvgPlot::addVerticalLine(double x, const std::string& colour, const std::string& label,
                              double widthPx, const std::string& dash) {
  items_.push_back({Item::VLine, {x}, {}, colour, label, dash, widthPx});
}

void SvgPlot::addHorizontalLine(double y, const std::string& colour, const std::string& label,
                                double widthPx, const std::string& dash) {
  items_.push_back({Item::HLine, {}, {y}, colour, label, dash, widthPx});
}

void SvgPlot::addPoint(double x, double y, const std::string& colour, double radiusPx) {
  items_.push_back({Item::Point, {x}, {y}, colour, "", "", radiusPx});
}

std::string SvgPlot::render() const {
  const double pw = width_ - kLeft - kRight, ph = height_ - kTop - kBottom;
  auto px = [&](double x) { return kLeft + (x - xMin_) / (xMax_ - xMin_) * pw; };
  auto py = [&](double y) { return kTop + (1 - (y - yMin_) / (yMax_ - yMin_)) * ph; };
  auto stroke = [](const Item& it) {
    std::string s =
        fmt::format(R"(stroke="{}" stroke-width="{:g}" fill="none")", it.colour, it.width);
    if (!it.dash.empty()) s += fmt::format(R"( stroke-dasharray="{}")", it.dash);
    return s;
  };

  std::string s = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" )"
      R"(font-family="DejaVu Sans, Arial, sans-serif" font-size="12">)"
      "\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width_, height_);
  s += fmt::format(R"(<text x="{:g}" y="24" font-size="15" font-weight="bold">{}</text>)", kLeft,
                   escape(title_)) +
       "\n";
  s +=
      fmt::format(
          R"(<defs><clipPath id="area"><rect x="{:g}" y="{:g}" width="{:g}" height="{:g}"/></clipPath></defs>)",
          kLeft, kTop, pw, ph) +
      "\n";

  // Grid, ticks and tick labels.
  const std::vector<double> xTicks = niceTicks(xMin_, xMax_, 8);
  const double xStep = xTicks.size() > 1 ? xTicks[1] - xTicks[0] : 1;
  for (double t : xTicks) {
    s += fmt::format(R"(<line x1="{0:.2f}" y1="{1:g}" x2="{0:.2f}" y2="{2:g}" stroke="#e4e4e4"/>)",
                     px(t), kTop, kTop + ph) +
         "\n";
    s += fmt::format(R"(<line x1="{0:.2f}" y1="{1:g}" x2="{0:.2f}" y2="{2:g}" stroke="#333"/>)",
                     px(t), kTop + ph, kTop + ph + 5) +
         "\n";
    s += fmt::format(R"(<text x="{:.2f}" y="{:g}" text-anchor="middle">{}</text>)", px(t),
                     kTop + ph + 19, tickLabel(t, xStep)) +
         "\n";
  }
  const std::vector<double> yTicks = niceTicks(yMin_, yMax_, 6);
  const double yStep = yTicks.size() > 1 ? yTicks[1] - yTicks[0] : 1;
  for (double t : yTicks) {
    s += fmt::format(R"(<line x1="{0:g}" y1="{1:.2f}" x2="{2:g}" y2="{1:.2f}" stroke="#e4e4e4"/>)",
                     kLeft, py(t), kLeft + pw) +
         "\n";
    s += fmt::format(R"(<line x1="{0:g}" y1="{1:.2f}" x2="{2:g}" y2="{1:.2f}" stroke="#333"/>)",
                     kLeft - 5, py(t), kLeft) +
         "\n";
    s += fmt::format(R"(<text x="{:g}" y="{:.2f}" text-anchor="end">{}</text>)", kLeft - 8,
                     py(t) + 4, tickLabel(t, yStep)) +
         "\n";
  }
  s += fmt::format(
           R"(<rect x="{:g}" y="{:g}" width="{:g}" height="{:g}" fill="none" stroke="#333"/>)",
           kLeft, kTop, pw, ph) +
       "\n";
  s += fmt::format(R"(<text x="{:g}" y="{:g}" text-anchor="middle">{}</text>)", kLeft + pw / 2,
                   double(height_) - 14, escape(xLabel_)) +
       "\n";
  s +=
      fmt::format(
          R"svg(<text transform="translate(20 {:g}) rotate(-90)" text-anchor="middle">{}</text>)svg",
          kTop + ph / 2, escape(yLabel_)) +
      "\n";

  // Data, clipped to the plot area.
  s += "<g clip-path=\"url(#area)\">\n";
  for (const Item& it : items_) {
    switch (it.kind) {
      case Item::Line: {
        std::string pts;
        for (size_t k = 0; k < it.x.size(); ++k)
          pts += fmt::format("{:.2f},{:.2f} ", px(it.x[k]), py(it.y[k]));
        s += fmt::format(R"(<polyline points="{}" {} stroke-linejoin="round"/>)", pts, stroke(it)) +
             "\n";
        break;
      }
      case Item::VLine:
        s += fmt::format(R"(<line x1="{0:.2f}" y1="{1:g}" x2="{0:.2f}" y2="{2:g}" {3}/>)",
                         px(it.x[0]), kTop, kTop + ph, stroke(it)) +
             "\n";
        break;
      case Item::HLine:
        s += fmt::format(R"(<line x1="{0:g}" y1="{1:.2f}" x2="{2:g}" y2="{1:.2f}" {3}/>)", kLeft,
                         py(it.y[0]), kLeft + pw, stroke(it)) +
             "\n";
        break;
      case Item::Point:
        s += fmt::format(R"(<circle cx="{:.2f}" cy="{:.2f}" r="{:g}" fill="{}" stroke="white"/>)",
                         px(it.x[0]), py(it.y[0]), it.width, it.colour) +
             "\n";
        break;
    }
  }
  s += "</g>\n";

  // Legend, top left inside the plot area (a profile rising to the right leaves it free).
  std::vector<const Item*> legend;
  for (const Item& it : items_)
    if (!it.label.empty()) legend.push_back(&it);
  if (!legend.empty()) {
    size_t longest = 0;
    for (const Item* it : legend) longest = std::max(longest, it->label.size());
    const double lw = 40 + 6.6 * double(longest), lh = 8 + 18 * double(legend.size());
    s +=
        fmt::format(
            R"(<rect x="{:g}" y="{:g}" width="{:g}" height="{:g}" fill="white" fill-opacity="0.9" stroke="#999"/>)",
            kLeft + 10, kTop + 10, lw, lh) +
        "\n";
    for (size_t k = 0; k < legend.size(); ++k) {
      const double y = kTop + 10 + 16 + 18 * double(k);
      s += fmt::format(R"(<line x1="{:g}" y1="{:g}" x2="{:g}" y2="{:g}" {}/>)", kLeft + 18, y - 4,
                       kLeft + 42, y - 4, stroke(*legend[k])) +
           "\n";
      s += fmt::format(R"(<text x="{:g}" y="{:g}">{}</text>)", kLeft + 48, y,
                       escape(legend[k]->label)) +
           "\n";
    }
  }
  s += "</svg>\n";
  return s;
}

void writeSvgFile(const std::string& path, const std::string& svgText) {
  writeTextAtomically(path, svgText, "the picture");
}

}  // namespace scallop
