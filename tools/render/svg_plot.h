// SvgPlot: a small hand-written SVG line plot (axes with ticks and labels, polylines,
// reference lines, points and a legend), enough for the validation pictures. No
// dependency: SVG is text, and any browser shows it.
#pragma once

#include <string>
#include <vector>

namespace scallop {

// About `count` round tick values (1, 2 or 5 times a power of ten) covering [lo, hi].
std::vector<double> niceTicks(double lo, double hi, int count = 6);

class SvgPlot {
 public:
  SvgPlot(int widthPx = 760, int heightPx = 480) : width_(widthPx), height_(heightPx) {}

  void setTitle(std::string title) { title_ = std::move(title); }
  void setLabels(std::string x, std::string y) { xLabel_ = std::move(x), yLabel_ = std::move(y); }
  // Data ranges shown; data outside is clipped to the plot area.
  void setRange(double xMin, double xMax, double yMin, double yMax);

  // `colour` is any SVG colour; `dash` an SVG stroke-dasharray ("" for solid). An
  // empty `label` keeps the item out of the legend.
  void addLine(const std::vector<double>& x, const std::vector<double>& y,
               const std::string& colour, const std::string& label, double widthPx = 2,
               const std::string& dash = "");
  void addVerticalLine(double x, const std::string& colour, const std::string& label,
                       double widthPx = 1.5, const std::string& dash = "");
  void addHorizontalLine(double y, const std::string& colour, const std::string& label,
                         double widthPx = 1.5, const std::string& dash = "");
  void addPoint(double x, double y, const std::string& colour, double radiusPx = 3.5);

  std::string render() const;

 private:
  struct Item {
    enum Kind { Line, VLine, HLine, Point } kind;
    std::vector<double> x, y;
    std::string colour, label, dash;
    double width;
  };
  int width_, height_;
  std::string title_, xLabel_, yLabel_;
  double xMin_ = 0, xMax_ = 1, yMin_ = 0, yMax_ = 1;
  std::vector<Item> items_;
};

// Writes `svgText` to `path` atomically (tools/io/atomic_file.h); InputError on failure.
void writeSvgFile(const std::string& path, const std::string& svgText);

}  // namespace scallop
