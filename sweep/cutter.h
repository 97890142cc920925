// Cutter: the milling tool as a solid of revolution (CONVENTIONS.md "Cutters").
//
// In the tool frame (tip at the origin, axis a, s = height along a) every cutter is
//     K = ( Cyl(Rb; s in [r, L]) (+) Ball(r) )  intersected with  { s <= L }
// where Rb = R - r is the radius of the flat bottom, r the corner radius and L the
// flute length. ball: Rb = 0, r = R.  flat: r = 0.  bull: 0 < r < R.
// K is convex; this is what makes the swept-solid heights exact and cheap.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sweep/cutter_profile.h"
#include "sweep/tooth_geometry.h"

namespace scallop {

// Ball, flat and bull have their own kernel; every other type is a CutterProfile
// (CONVENTIONS.md "Cutter shapes": the named types' parameters; `profile` a free chain).
enum class CutterType {
  Ball,
  Flat,
  Bull,
  TaperBall,
  TaperBull,
  Cone,
  Barrel,
  TaperBarrel,
  Oval,
  Lens,
  Profile
};

const char* toString(CutterType type);
// Parses "ball" | "flat" | "bull"; throws InputError naming `field` otherwise.
CutterType parseCutterType(const std::string& name, const std::string& field = "tool.type");

// The cutting edges (cutter keys `flutes`, `helix_deg`, `runout_mm`,
// `runout_phase_deg`: docs/teeth.md, docs/algorithm.md). Only the "teeth" cutting model reads
// them; the envelope model sweeps the solid of revolution.
//   * `flutes` teeth at body angles psi_k = 2 pi k / flutes, each an edge running along
//     the whole meridian profile: from the axis across the flat bottom (radius Rb),
//     round the corner (r) and up the flank (radius R) to the flute length L.
//   * A helix of angle beta puts the edge point at height h above the tip at body angle
//     psi_k + h tan(beta) / R (a right-hand helix, cutting clockwise, M3).
//   * Runout: the cutter's own axis sits `runout` mm off the spindle axis, in the body
//     direction at angle `runoutPhaseDeg` from tooth 0, and turns with the spindle.
//   * Per tooth (tooth_geometry.h): body angles other than 2 pi k / flutes (unequal
//     pitch, `tooth_angles_deg`) and each edge moved radially and axially
//     (`tooth_offsets`); runout composes with them.
//   * Edges on a span of the profile (`edge_span`, `tooth_edge_spans`, EdgeSpan): an
//     insert covers part of the profile only, the body behind the rest not cutting.
//   * Rake (`rake_deg`, `tooth_rakes_deg`, ToothRake): the edge lies on a plane turned
//     out of the meridian, so its point at (rho, h) trails by RakeLag's angle.
struct CutterTeeth {
  int flutes = 2;
  double helixDeg = 0;        // beta, degrees, in [0, 60]
  double runout = 0;          // mm, in [0, R / 10]
  double runoutPhaseDeg = 0;  // degrees, any finite angle
  // The per-tooth tables, each one entry per flute or empty (the default):
  //   toothAnglesDeg  body angles, degrees (empty: 360 k / flutes)
  //   toothOffsets    offsets (empty: none)
  //   edgeSpans       spans of the profile (empty: every edge whole)
  //   toothRakes      rakes (empty: none)
  // They sit behind one shared pointer (null while all are empty): a Cutter is copied
  // into every swept move, twice more into a constant-axis move's segment, so four
  // vectors there cost 96 bytes a copy and the pointer 16 (docs/performance.md, "Memory
  // a move"). Read them here; edit*() gives a table of this CutterTeeth's own (copied
  // first when shared), for building a cutter, not while moves share it.
  const std::vector<double>& toothAnglesDeg() const { return table().anglesDeg; }
  const std::vector<ToothOffset>& toothOffsets() const { return table().offsets; }
  const std::vector<EdgeSpan>& edgeSpans() const { return table().spans; }
  const std::vector<ToothRake>& toothRakes() const { return table().rakes; }
  std::vector<double>& editToothAnglesDeg() { return edit().anglesDeg; }
  std::vector<ToothOffset>& editToothOffsets() { return edit().offsets; }
  std::vector<EdgeSpan>& editEdgeSpans() { return edit().spans; }
  std::vector<ToothRake>& editToothRakes() { return edit().rakes; }

  // Tooth k's body angle psi_k, radians.
  double toothAngle(int k) const;
  ToothOffset toothOffset(int k) const {
    return toothOffsets().empty() ? ToothOffset{} : toothOffsets()[size_t(k)];
  }
  ToothRake toothRake(int k) const {
    return toothRakes().empty() ? ToothRake{} : toothRakes()[size_t(k)];
  }
  // The largest outward radial offset and the largest axial one towards the tip, mm
  // (0 when no tooth reaches beyond the nominal edge).
  double radialReach() const;
  double axialReach() const;

  // Validates; throws InputError naming `fieldPrefix` + ".flutes" (an integer 1..16),
  // ".helix_deg", ".runout_mm" (needs the cutter's radius) or ".runout_phase_deg".
  static CutterTeeth make(int flutes, double helixDeg, double runout, double runoutPhaseDeg,
                          double cutterRadius, const std::string& fieldPrefix = "tool");

 private:
  struct Table {
    std::vector<double> anglesDeg;
    std::vector<ToothOffset> offsets;
    std::vector<EdgeSpan> spans;
    std::vector<ToothRake> rakes;
  };
  const Table& table() const;
  Table& edit();
  std::shared_ptr<Table> table_;
};

struct Cutter {
  CutterType type = CutterType::Ball;
  double radius = 0;        // R, mm
  double cornerRadius = 0;  // r, mm (R for ball, 0 for flat)
  double fluteLength = 0;   // L, mm: height of the cylindrical part's top above the tip

  // Validates and builds a cutter. `cornerRadius` is only read for bull cutters;
  // `fluteLength` <= 0 means the default 4 R. Throws InputError naming
  // `fieldPrefix` + ".radius" / ".corner_radius" / ".flute_length".
  static Cutter make(CutterType type, double radius, double cornerRadius = 0,
                     double fluteLength = 0, const std::string& fieldPrefix = "tool");

  double bottomRadius() const { return radius - cornerRadius; }  // Rb, mm
  // The profile's arc length from the axis at the tip to the flute top, mm: the length
  // of a whole edge (EdgeSpan's parameter).
  double edgeLength() const;
  // The arc length from the axis at the tip to the profile's point at height h above
  // the tip and radius rho from the axis (EdgeSpan's parameter), mm; and the smallest
  // and largest radius of the profile's points on `span`, mm.
  double edgeArcLength(double h, double rho) const;
  void edgeSpanRadii(const EdgeSpan& span, double* lo, double* hi) const;
  // The profile's point at arc length u along it: its radius rho and height h, mm.
  void edgeSpot(double u, double* rho, double* h) const;
  // Tooth k's rake lag (tooth_geometry.h), its face through the nominal profile's point
  // at the start of the tooth's span (the tip's axis for a whole edge).
  RakeLag rakeLag(int k) const;
  // Validates where the teeth's rake faces meet the profile: every point of each raked
  // tooth's span (sampled every 1/4096 of it, and its ends) has |D| <= rho sin(60 deg).
  // Throws InputError naming `field` and the tooth otherwise.
  void checkRakes(const std::string& field) const;

  CutterTeeth teeth;  // read by the "teeth" cutting model only

  // Every type but ball, flat and bull: its profile (then `radius` is its largest
  // radius, `fluteLength` its L, `cornerRadius` 0), swept by the general kernel; null
  // for ball, flat and bull.
  std::shared_ptr<const CutterProfile> profile;
  bool general() const { return profile != nullptr; }

  // The solid of revolution about the spindle axis that holds the cutter at every
  // spindle angle: the profile pushed out by the runout and the largest outward radial
  // tooth offset (Rb + runout + radialReach, r, L), so a ball with runout becomes a
  // bull. The cutter itself without either. Teeth reaching below the tip
  // (teeth.axialReach() > 0) lie in it once it is lowered by that much along the axis
  // (sweepToolPath lowers the moves it sweeps). Its heights are then a proven lower
  // bound of the teeth's (every edge point lies inside it).
  Cutter spindleEnvelope() const;
};

}  // namespace scallop
