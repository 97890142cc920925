// The box, its ticks and labels (render_box.h).
#include "tools/render/render_box.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace scallop {

namespace {

struct Painter {
  png::Canvas& canvas;
  int offsetX, offsetY;
  const Camera& camera;
  const TracedImage& traced;
  int thickness;

  // The 3-D segment a-b, one pixel at a time, where nothing traced lies in front of it.
  void line(const Vec3& a, const Vec3& b) const {
    const auto pa = camera.pixelOf(a), pb = camera.pixelOf(b);
    const int steps = 1 + int(2 * std::hypot(pb[0] - pa[0], pb[1] - pa[1]));
    for (int k = 0; k <= steps; ++k) {
      const Vec3 p = a + (b - a) * (double(k) / steps);
      const auto px = camera.pixelOf(p);
      const int c = int(std::floor(px[0])), r = int(std::floor(px[1]));
      if (c >= 0 && r >= 0 && c < traced.width && r < traced.height) {
        const float front = traced.depth[size_t(r) * size_t(traced.width) + size_t(c)];
        // Two pixels' depth of slack: the box's foot meets the walls' foot.
        if (camera.depthOf(p) > double(front) + 2 * camera.mmPerPxAt(p)) continue;
      }
      canvas.fill(offsetX + c - thickness / 2, offsetY + r - thickness / 2, thickness, thickness,
                  png::kFrame);
    }
  }

  std::array<double, 2> screen(const Vec3& p) const {
    const auto q = camera.pixelOf(p);
    return {q[0] + offsetX, q[1] + offsetY};
  }
};

// Round tick values in [lo, hi]: at most `most` of them, 1, 2 or 5 times a power of ten
// apart.
std::vector<double> tickValues(double lo, double hi, int most, int& decimals) {
  double step = png::niceBelow((hi - lo) / std::max(1, most));
  for (int tries = 0; tries < 8; ++tries) {
    const double first = std::ceil(lo / step - 1e-9) * step;
    const int count = int(std::floor((hi - first) / step + 1e-9)) + 1;
    if (count <= most + 1) break;
    const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    step *= m < 1.5 ? 2 : m < 3 ? 2.5 : 2;
  }
  decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
  std::vector<double> values;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
    values.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  return values;
}

// The ticks of one edge from `from` to `to` (world), `outward` the unit vector away
// from the box in the base plane; `along` picks the coordinate that the labels give.
void drawEdgeTicks(const Painter& paint, const Vec3& from, const Vec3& to, const Vec3& outward,
                   bool alongX, const std::string& axisName, int scale) {
  const int textH = png::kCapHeightPx * scale;
  const auto a = paint.screen(from), b = paint.screen(to);
  const double lengthPx = std::hypot(b[0] - a[0], b[1] - a[1]);
  const double lo = alongX ? from.x : from.y, hi = alongX ? to.x : to.y;
  int decimals = 0;
  const int widest =
      png::textWidth(fmt::format("{:.2f}", std::max(std::abs(lo), std::abs(hi))), scale);
  const int most = std::clamp(int(lengthPx / (widest + 2 * textH)), 2, 10);
  const std::vector<double> values = tickValues(lo, hi, most, decimals);
  const Vec3 mid = (from + to) * 0.5;
  const double tickMm = 6 * scale * paint.camera.mmPerPxAt(mid);
  // The edge's outward direction on the picture.
  const auto m0 = paint.screen(mid), m1 = paint.screen(mid + outward * tickMm);
  double ux = m1[0] - m0[0], uy = m1[1] - m0[1];
  const double un = std::hypot(ux, uy);
  if (un < 1e-9) return;  // the edge is seen end on
  ux /= un, uy /= un;
  int labelReach = 0;
  for (double v : values) {
    const Vec3 p = alongX ? Vec3(v, from.y, from.z) : Vec3(from.x, v, from.z);
    paint.line(p, p + outward * tickMm);
    const std::string label = fmt::format("{:.{}f}", v, decimals);
    const int w = png::textWidth(label, scale);
    const double reach = 4 * scale + 0.5 * (std::abs(ux) * w + std::abs(uy) * textH);
    labelReach = std::max(labelReach, int(std::ceil(2 * reach)));
    const auto e = paint.screen(p + outward * tickMm);
    paint.canvas.text(int(std::lround(e[0] + ux * reach - 0.5 * w)),
                      int(std::lround(e[1] + uy * reach - 0.5 * textH)), label, scale, png::kInk);
  }
  const int w = png::textWidth(axisName, scale);
  if (std::abs(ux) > std::abs(uy)) {
    // Labels beside a steep edge: the name above the edge's upper end, over its labels.
    const Vec3 top = a[1] < b[1] ? from : to;
    const auto e = paint.screen(top + outward * tickMm);
    const double x = e[0] + ux * 0.5 * labelReach;
    paint.canvas.text(int(std::lround(x - 0.5 * w)), int(std::lround(e[1] - 2.5 * textH)), axisName,
                      scale, png::kInk);
    return;
  }
  const double reach = labelReach + 6 * scale + 0.5 * (std::abs(ux) * w + std::abs(uy) * textH);
  const auto e = paint.screen(mid + outward * tickMm);
  paint.canvas.text(int(std::lround(e[0] + ux * reach - 0.5 * w)),
                    int(std::lround(e[1] + uy * reach - 0.5 * textH)), axisName, scale, png::kInk);
}

}  // namespace

void drawRenderBox(png::Canvas& canvas, int offsetX, int offsetY, const Camera& camera,
                   const TracedImage& traced, const BoxFrame& box, int scale) {
  const Painter paint{canvas, offsetX, offsetY, camera, traced, std::max(1, scale)};
  const Vec3 sw(box.x0, box.y0, box.z), se(box.x1, box.y0, box.z);
  const Vec3 nw(box.x0, box.y1, box.z), ne(box.x1, box.y1, box.z);
  paint.line(sw, se), paint.line(se, ne), paint.line(ne, nw), paint.line(nw, sw);

  // The edges nearest the viewer: lowest on the picture (then leftmost).
  auto lower = [&](const Vec3& a1, const Vec3& a2, const Vec3& b1, const Vec3& b2) {
    const auto a = paint.screen((a1 + a2) * 0.5), b = paint.screen((b1 + b2) * 0.5);
    return std::abs(a[1] - b[1]) > 1 ? a[1] > b[1] : a[0] <= b[0];
  };
  const bool south = lower(sw, se, nw, ne);
  const double yEdge = south ? box.y0 : box.y1;
  drawEdgeTicks(paint, Vec3(box.x0, yEdge, box.z), Vec3(box.x1, yEdge, box.z),
                Vec3(0, south ? -1 : 1, 0), true, "x (mm)", scale);
  const bool west = lower(sw, nw, se, ne);
  const double xEdge = west ? box.x0 : box.x1;
  drawEdgeTicks(paint, Vec3(xEdge, box.y0, box.z), Vec3(xEdge, box.y1, box.z),
                Vec3(west ? -1 : 1, 0, 0), false, "y (mm)", scale);
}

}  // namespace scallop
