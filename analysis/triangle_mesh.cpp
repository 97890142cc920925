#include "analysis/triangle_mesh.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "base/fnv1a.h"

namespace scallop {

Box3 TriangleMesh::bounds() const {
  Box3 b;
  for (const Vec3& v : vertices) b.extend(v);
  return b;
}

namespace {

// Exact-position key: STL repeats each shared vertex bit for bit, so welding needs no
// tolerance (and a tolerance would silently move the design surface). -0 and +0 weld.
struct PositionKey {
  uint64_t bits[3];
  bool operator==(const PositionKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    Fnv1a hash;  // word-wise, each word's high bits folded down for the buckets
    for (uint64_t b : k.bits) hash.addWord(b), hash.value ^= hash.value >> 29;
    return size_t(hash.value);
  }
};
PositionKey keyOf(const Vec3& p) {
  PositionKey k;
  const double c[3] = {p.x + 0.0, p.y + 0.0, p.z + 0.0};  // + 0.0 turns -0 into +0
  for (int i = 0; i < 3; ++i) std::memcpy(&k.bits[i], &c[i], sizeof(double));
  return k;
}

}  // namespace

TriangleMesh meshFromTriangles(const std::vector<std::array<Vec3, 3>>& soup, MeshRepairs* repairs) {
  TriangleMesh mesh;
  MeshRepairs local;
  MeshRepairs& rep = repairs ? *repairs : local;
  rep.inputTriangles = soup.size();
  std::unordered_map<PositionKey, uint32_t, PositionHash> index;
  index.reserve(soup.size());
  auto weld = [&](const Vec3& p) {
    auto [it, inserted] = index.try_emplace(keyOf(p), uint32_t(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(p);
    return it->second;
  };
  for (size_t t = 0; t < soup.size(); ++t) {
    const auto& tri = soup[t];
    const std::array<uint32_t, 3> f = {weld(tri[0]), weld(tri[1]), weld(tri[2])};
    const Vec3 n = cross(tri[1] - tri[0], tri[2] - tri[0]);
    const double len = length(n);
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || !(len > 0) || !std::isfinite(len)) {
      ++rep.degenerateDropped;
      if (rep.firstDegenerate.size() < 10) rep.firstDegenerate.push_back(t + 1);
      continue;
    }
    mesh.triangles.push_back(f);
    mesh.normals.push_back(n / len);
  }
  return mesh;
}

size_t orientNormalsUp(TriangleMesh& mesh) {
  size_t flipped = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.normals[t].z >= 0) continue;
    std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    mesh.normals[t] = -mesh.normals[t];
    ++flipped;
  }
  return flipped;
}

// ---- Embree ------------------------------------------------------------------------

struct MeshIndex::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  double slack = 0;  // mm: float rounding of the boxes and of a ray's distance
  double topZ = 0;   // rays start here, above the mesh
  std::string lastError;
};

namespace {

void deviceError(void* user, RTCError, const char* message) {
  *static_cast<std::string*>(user) = std::string("Embree: ") + message;
}

bool collect(RTCPointQueryFunctionArguments* args) {
  static_cast<std::vector<uint32_t>*>(args->userPtr)->push_back(args->primID);
  return false;  // the query ball is never shrunk: we want every candidate
}

}  // namespace

MeshIndex::MeshIndex(const TriangleMesh& mesh) : mesh_(mesh), impl_(std::make_unique<Impl>()) {
  if (mesh.triangles.empty()) throw std::runtime_error("MeshIndex: the mesh has no triangles");
  if (mesh.triangles.size() > UINT32_MAX / 2)
    throw std::runtime_error("MeshIndex: too many triangles");
  const Box3 box = mesh.bounds();
  const double reach = std::max({std::fabs(box.min.x), std::fabs(box.min.y), std::fabs(box.min.z),
                                 std::fabs(box.max.x), std::fabs(box.max.y), std::fabs(box.max.z)});
  // A float box corner is off by at most half an ulp of its coordinate; eight ulps and
  // a nanometre keep every query a superset.
  impl_->slack = 8.0 * reach * 0x1p-23 + 1e-6;
  impl_->topZ = box.max.z + 1.0 + (box.max.z - box.min.z);

  Impl& im = *impl_;
  im.device = rtcNewDevice(nullptr);
  if (!im.device) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(im.device, deviceError, &im.lastError);
  im.scene = rtcNewScene(im.device);
  // Robust traversal: a vertical ray exactly on a shared edge must not slip through.
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(im.scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size()));
  if (!v || !f)
    throw std::runtime_error(im.lastError.empty() ? "Embree: out of memory" : im.lastError);
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    v[3 * i] = float(mesh.vertices[i].x);
    v[3 * i + 1] = float(mesh.vertices[i].y);
    v[3 * i + 2] = float(mesh.vertices[i].z);
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) f[3 * t + k] = mesh.triangles[t][k];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(im.scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(im.scene);
  if (rtcGetDeviceError(im.device) != RTC_ERROR_NONE || !im.lastError.empty())
    throw std::runtime_error(im.lastError.empty() ? "Embree: scene build failed" : im.lastError);
}

MeshIndex::~MeshIndex() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

void MeshIndex::trianglesNear(const Vec3& centre, double radius, std::vector<uint32_t>& out) const {
  out.clear();
  RTCPointQuery q;
  q.x = float(centre.x), q.y = float(centre.y), q.z = float(centre.z);
  q.radius = float(radius + 2 * impl_->slack + 8.0 * radius * 0x1p-23);
  q.time = 0;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &q, &context, collect, &out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

namespace {

// Height of triangle t's plane at (x, y) if (x, y) is inside its xy projection
// (closed, with a relative 1e-12 allowance for round-off on an edge).
bool heightInside(const TriangleMesh& mesh, uint32_t t, double x, double y, double& z) {
  const auto c = mesh.corners(t);
  const double area = (c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x);
  if (area == 0) return false;  // vertical facet: no height
  double w[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = c[(k + 1) % 3];
    const Vec3& b = c[(k + 2) % 3];
    w[k] = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / area;
  }
  const double eps = -1e-12;
  if (w[0] < eps || w[1] < eps || w[2] < eps) return false;
  const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
  z = c[0].z - (n.x * (x - c[0].x) + n.y * (y - c[0].y)) / n.z;
  return true;
}

}  // namespace

bool MeshIndex::topHeight(double x, double y, double& z, uint32_t& triangle) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = float(x), rh.ray.org_y = float(y), rh.ray.org_z = float(impl_->topZ);
  rh.ray.dir_x = 0, rh.ray.dir_y = 0, rh.ray.dir_z = -1;
  rh.ray.tnear = 0, rh.ray.tfar = HUGE_VALF, rh.ray.time = 0;
  rh.ray.mask = 0xFFFFFFFFu, rh.ray.id = 0, rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  // Embree's hit is a float answer; the height is the highest exact plane height among
  // the facets near the hit that contain (x, y) (on a shared edge, or where two layers
  // are within float rounding, any of them may have been reported).
  const double zHit = impl_->topZ - double(rh.ray.tfar);
  const double r = 4 * impl_->slack + 1e-6 * (impl_->topZ - zHit);
  std::vector<uint32_t> near;
  trianglesNear({x, y, zHit}, r, near);
  bool found = false;
  for (uint32_t t : near) {
    double zt;
    if (heightInside(mesh_, t, x, y, zt) && (!found || zt > z)) z = zt, triangle = t, found = true;
  }
  if (found) return true;
  // Just outside every facet in double (the mesh's rim): use the hit facet's plane.
  triangle = rh.hit.primID;
  const auto c = mesh_.corners(triangle);
  const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
  if (n.z == 0) return false;
  z = c[0].z - (n.x * (x - c[0].x) + n.y * (y - c[0].y)) / n.z;
  return true;
}

}  // namespace scallop
