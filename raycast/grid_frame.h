// GridFrame: a height map along any direction (CONVENTIONS.md "Frames"). The map lies
// in the plane through `origin` spanned by u and v = normal x u; cell (i, j) is the line
// through origin + (i + 1/2)s u + (j + 1/2)s v along `normal`, and holds the height w
// along `normal` of the machined surface on it.
//
// A frame is a rigid motion: in frame coordinates (x, y, w) = ((p - origin).u,
// (p - origin).v, (p - origin).normal) the frame's heights are the ordinary z-map of the
// tool path moved into them, computed by the same exact kernel. A frame with u = +X and
// normal = +Z exactly is a translation along z only: it keeps the part's x and y (grid
// origin = origin.x, origin.y), so its heights are the map without a frame, bit for bit,
// less origin.z.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "base/vec3.h"
#include "raycast/zmap.h"
#include "sweep/pose.h"

namespace scallop {

struct GridFrame {
  Vec3 origin;              // mm, part frame
  Vec3 u{1, 0, 0};          // unit
  Vec3 normal{0, 0, 1};     // unit, at right angles to u
  Vec3 v{0, 1, 0};          // normal x u
  double sizeU = 0;         // the map's extent along u, mm
  double sizeV = 0;         // along v, mm
  double depth = HUGE_VAL;  // mm below the plane through origin that the map looks

  bool translationOnly() const { return u == Vec3{1, 0, 0} && normal == Vec3{0, 0, 1}; }
  // A point of the part in frame coordinates (x, y along the map, w along the normal).
  Vec3 pointToFrame(const Vec3& p) const;
  // A direction of the part (a tool axis) in frame coordinates.
  Vec3 directionToFrame(const Vec3& d) const;
  // The point of the part at frame coordinates (x, y, w).
  Vec3 pointFromFrame(double x, double y, double w) const;
  // The map's cells of side `spacing` (mm), in frame coordinates.
  GridSpec grid(double spacing) const;
  // One line for the height files' metadata: "origin (x, y, z) mm, u (...), v (...),
  // normal (...), depth d mm; heights along normal from the plane through origin".
  std::string describe() const;
};

// The frame of `u` and `normal` as given (any length): both normalised, v = normal x u.
// Throws InputError naming `field`.u or `field`.normal when one is zero or they are not
// at right angles within 1e-9 (|u.normal| after normalising).
GridFrame makeGridFrame(const Vec3& origin, const Vec3& u, const Vec3& normal, double sizeU,
                        double sizeV, double depth, const char* field);

// The path moved into the frame's coordinates: every tip and axis (rotary machine
// motions are defined by machine angles in the part frame and are not moved: the
// caller refuses them).
ToolPath pathInFrame(const ToolPath& path, const GridFrame& frame);

// The highest w of `stock` (a box of the part frame) seen in the frame: no swept solid
// above it changes the map.
double stockTopInFrame(const Box3& stock, const GridFrame& frame);

// Where the line of frame coordinates (x, y) leaves `stock` on the normal side (its
// largest w inside the box), or NaN where the line misses the box or meets it only
// below -depth: no material there.
double stockExitHeight(const Box3& stock, const GridFrame& frame, double x, double y);

// Heights of cells whose line holds no material while the map is cast: nothing lowers
// them (zmap_caster.h only lowers a cell), and finishFrameMap makes them NaN.
constexpr double kNoMaterial = -HUGE_VAL;

// Every cell of `map` set to its stock exit height, kNoMaterial where there is none.
void fillFrameStock(ZMap& map, const Box3& stock, const GridFrame& frame);

struct FrameCellCounts {
  int64_t voidCells = 0;        // lines that miss the stock: NaN
  int64_t cutThroughCells = 0;  // lines cut down to -depth: hold -depth
};

// After the cast: cells without material become NaN, cells cut below -depth hold
// -depth; returns how many of each.
FrameCellCounts finishFrameMap(ZMap& map, const GridFrame& frame);

// After the cast of a map without a frame on a stock of any shape: cells without material
// become NaN (counted as voidCells).
FrameCellCounts finishStockMap(ZMap& map);

}  // namespace scallop
