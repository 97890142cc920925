#include "tools/render/cutter_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "tools/io/xml_text.h"

namespace scallop {

namespace {

constexpr double kPictureWidthPx = 240, kDrawingHeightPx = 300, kMarginPx = 24;
constexpr double kTitlePx = 22, kFootPx = 34;

}  // namespace

std::string cutterProfileSvg(const Cutter& cutter, const std::string& title) {
  const CutterProfile profile = cutter.general() ? *cutter.profile : CutterProfile::of(cutter);
  const std::vector<ProfileSegment>& chain = profile.segments();
  const double R = profile.maxRadius(), L = profile.fluteLength();
  // One scale (px per mm) for both directions, so the picture has the tool's proportions.
  const double scale =
      std::min((kPictureWidthPx - 2 * kMarginPx) / (2 * R), (kDrawingHeightPx - 2 * kMarginPx) / L);
  const double axisX = kPictureWidthPx / 2;
  const double tipY = kTitlePx + kDrawingHeightPx - kMarginPx;
  auto x = [&](double rho) { return axisX + rho * scale; };
  auto y = [&](double s) { return tipY - s * scale; };

  // The silhouette: up the right side, across the cap, down the mirrored left side. With
  // y pointing down, the chain's counter-clockwise arcs (and their mirror images walked
  // backwards) are all SVG's positive sweep; each is the shorter arc.
  std::string path = fmt::format("M {:.4f} {:.4f}", x(0), y(0));
  auto edge = [&](double rho, double s, double radius) {
    if (radius > 0)
      path += fmt::format(" A {:.4f} {:.4f} 0 0 1 {:.4f} {:.4f}", radius * scale, radius * scale,
                          x(rho), y(s));
    else
      path += fmt::format(" L {:.4f} {:.4f}", x(rho), y(s));
  };
  for (const ProfileSegment& seg : chain) edge(seg.rho1, seg.s1, seg.arcRadius);
  edge(-chain.back().rho1, L, 0);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) edge(-it->rho0, it->s0, it->arcRadius);
  path += " Z";

  const double height = kTitlePx + kDrawingHeightPx + kFootPx;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:g}\" height=\"{1:g}\" "
      "viewBox=\"0 0 {0:g} {1:g}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{2:g}\" y=\"15\" text-anchor=\"middle\" font-weight=\"bold\">{3}</text>\n"
      "<path d=\"{4}\" fill=\"#c9d6e3\" stroke=\"#1f3b57\" stroke-width=\"1.5\" "
      "stroke-linejoin=\"round\"/>\n"
      "<line x1=\"{2:g}\" y1=\"{5:.4f}\" x2=\"{2:g}\" y2=\"{6:.4f}\" stroke=\"#888\" "
      "stroke-dasharray=\"6 3 1 3\"/>\n",
      kPictureWidthPx, height, axisX, xmlEscape(title), path, y(-0.05 * L) + 4, y(L) - 8);
  // The joins of the chain (right side): where one segment gives way to the next.
  for (const ProfileSegment& seg : chain)
    svg += fmt::format("<circle cx=\"{:.4f}\" cy=\"{:.4f}\" r=\"2.5\" fill=\"#d1495b\"/>\n",
                       x(seg.rho1), y(seg.s1));
  svg += fmt::format(
      "<text x=\"{:g}\" y=\"{:.4f}\" text-anchor=\"middle\">max radius {:.4g} mm, L {:.4g} "
      "mm</text>\n",
      axisX, tipY + kMarginPx + 16, R, L);
  svg += "</svg>\n";
  return svg;
}

}  // namespace scallop
