#include "tools/run/surface_run.h"

#include <fmt/core.h>

#include "base/input_error.h"
#include "tools/io/stl_io.h"

namespace scallop {

nlohmann::json writeAnalyticSurface(SurfaceSettings s) {
  s.spec.shape = parseSurfaceShape(s.shape);
  if (s.output.empty()) throw InputError("-o", "an output STL file is required");
  const TriangleMesh mesh = makeAnalyticSurface(s.spec);
  const std::string header = fmt::format("scallop surface {} {:g} x {:g} mm h={:g} mm", s.shape,
                                         s.spec.sizeX, s.spec.sizeY, s.spec.heightOrDefault());
  writeStl(mesh, s.output, s.ascii ? StlFormat::Ascii : StlFormat::Binary, header);
  const Box3 box = mesh.bounds();
  nlohmann::json j = {{"output", s.output},
                      {"format", s.ascii ? "ascii" : "binary"},
                      {"shape", s.shape},
                      {"size_mm", {s.spec.sizeX, s.spec.sizeY}},
                      {"height_mm", s.spec.heightOrDefault()},
                      {"triangles", mesh.triangles.size()},
                      {"vertices", mesh.vertices.size()},
                      {"z_range_mm", {box.min.z, box.max.z}}};
  if (s.spec.shape == SurfaceShape::Trough) j["trough_radius_mm"] = s.spec.troughRadiusOrDefault();
  return j;
}

}  // namespace scallop
