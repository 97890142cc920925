// Embree user geometry over the surface's tiles: bounds, intersect and occluded
// callbacks (surface_scene.h).
#include "tools/render/surface_scene.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/internal_error.h"

namespace scallop {

namespace {

// A ray as the callbacks see it: the double ray and the best hit so far ride behind
// Embree's context (the context is the first member, so its address is the struct's).
struct RayContext {
  RTCIntersectContext embree;
  Vec3 o, d;
  double tNear = 0, tFar = HUGE_VAL;
  PatchHit hit;
  bool occluded = false;
};

void deviceError(void* user, RTCError, const char* message) {
  *static_cast<std::string*>(user) = message ? message : "unknown Embree error";
}

float floatBelow(double x) {
  const float f = float(x);
  return double(f) <= x ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}

float floatAbove(double x) {
  const float f = float(x);
  return double(f) >= x ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

}  // namespace

struct SurfaceScene::Impl {
  const SurfaceGrid* surface = nullptr;
  int64_t tilesX = 0, tilesY = 0;
  // The tiles drawn (at least one patch without a NaN node): their index ty * tilesX +
  // tx, and their heights' world range.
  std::vector<int64_t> tile;
  std::vector<float> zLo, zHi;
  float pad = 0;  // bounds padding for Embree's float ray origins, world mm
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string lastError;

  // Patches [i0, i1) x [j0, j1) of tile k.
  void patchesOf(unsigned k, int64_t& i0, int64_t& j0, int64_t& i1, int64_t& j1) const {
    const int64_t t = tile[k], n = SurfaceScene::kTilePatches;
    i0 = (t % tilesX) * n, j0 = (t / tilesX) * n;
    i1 = std::min(i0 + n, surface->nx() - 1), j1 = std::min(j0 + n, surface->ny() - 1);
  }

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const Impl* im = static_cast<const Impl*>(args->geometryUserPtr);
    int64_t i0, j0, i1, j1;
    im->patchesOf(args->primID, i0, j0, i1, j1);
    const SurfaceGrid& s = *im->surface;
    RTCBounds* b = args->bounds_o;
    b->lower_x = floatBelow(s.nodeX(i0)) - im->pad, b->upper_x = floatAbove(s.nodeX(i1)) + im->pad;
    b->lower_y = floatBelow(s.nodeY(j0)) - im->pad, b->upper_y = floatAbove(s.nodeY(j1)) + im->pad;
    b->lower_z = im->zLo[args->primID] - im->pad, b->upper_z = im->zHi[args->primID] + im->pad;
  }

  static void intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const Impl* im = static_cast<const Impl*>(args->geometryUserPtr);
    RayContext* ray = reinterpret_cast<RayContext*>(args->context);
    int64_t i0, j0, i1, j1;
    im->patchesOf(args->primID, i0, j0, i1, j1);
    const PatchHit h = firstHitInTile(*im->surface, i0, j0, i1, j1, ray->o, ray->d, ray->tNear,
                                      std::min(ray->tFar, ray->hit.t), false);
    if (!h.found() || !h.before(ray->hit)) return;
    ray->hit = h;
    RTCRayN* r = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    // Embree prunes what lies beyond tfar: rounded up, a tie at the same t is still tried.
    RTCRayN_tfar(r, args->N, 0) = floatAbove(h.t);
    RTCHitN_u(hit, args->N, 0) = float(h.u), RTCHitN_v(hit, args->N, 0) = float(h.v);
    RTCHitN_Ng_x(hit, args->N, 0) = 0, RTCHitN_Ng_y(hit, args->N, 0) = 0;
    RTCHitN_Ng_z(hit, args->N, 0) = 1;
    RTCHitN_primID(hit, args->N, 0) = args->primID;
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_instID(hit, args->N, 0, 0) = args->context->instID[0];
  }

  static void occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    const Impl* im = static_cast<const Impl*>(args->geometryUserPtr);
    RayContext* ray = reinterpret_cast<RayContext*>(args->context);
    int64_t i0, j0, i1, j1;
    im->patchesOf(args->primID, i0, j0, i1, j1);
    if (firstHitInTile(*im->surface, i0, j0, i1, j1, ray->o, ray->d, ray->tNear, ray->tFar, true)
            .found()) {
      ray->occluded = true;
      RTCRayN_tfar(args->ray, args->N, 0) = -std::numeric_limits<float>::infinity();
    }
  }
};

SurfaceScene::SurfaceScene(const SurfaceGrid& surface) : surface_(surface), impl_(new Impl) {
  Impl& im = *impl_;
  im.surface = &surface;
  const int64_t n = kTilePatches;
  im.tilesX = (surface.nx() - 1 + n - 1) / n, im.tilesY = (surface.ny() - 1 + n - 1) / n;

  // Each tile's world height range over its patches without a NaN node, in parallel;
  // then the tiles with any such patch, in index order.
  const int64_t tiles = im.tilesX * im.tilesY;
  std::vector<float> lo(size_t(tiles), HUGE_VALF), hi(size_t(tiles), -HUGE_VALF);
  tbb::parallel_for(
      tbb::blocked_range<int64_t>(0, tiles), [&](const tbb::blocked_range<int64_t>& r) {
        for (int64_t t = r.begin(); t < r.end(); ++t) {
          const int64_t i0 = (t % im.tilesX) * n, j0 = (t / im.tilesX) * n;
          const int64_t i1 = std::min(i0 + n, surface.nx() - 1),
                        j1 = std::min(j0 + n, surface.ny() - 1);
          double a = HUGE_VAL, b = -HUGE_VAL;
          for (int64_t j = j0; j < j1; ++j)
            for (int64_t i = i0; i < i1; ++i) {
              const double z00 = surface.height(i, j), z10 = surface.height(i + 1, j);
              const double z01 = surface.height(i, j + 1), z11 = surface.height(i + 1, j + 1);
              if (std::isnan(z00 + z10 + z01 + z11)) continue;
              for (double z : {z00, z10, z01, z11}) {
                const double w = surface.worldZ(z);
                a = std::min(a, w), b = std::max(b, w);
              }
            }
          if (a <= b) lo[size_t(t)] = floatBelow(a), hi[size_t(t)] = floatAbove(b);
        }
      });
  double extent = std::max({std::abs(surface.nodeX(0)), std::abs(surface.nodeX(surface.nx() - 1)),
                            std::abs(surface.nodeY(0)), std::abs(surface.nodeY(surface.ny() - 1))});
  for (int64_t t = 0; t < tiles; ++t)
    if (lo[size_t(t)] <= hi[size_t(t)]) {
      im.tile.push_back(t);
      im.zLo.push_back(lo[size_t(t)]), im.zHi.push_back(hi[size_t(t)]);
      extent = std::max({extent, double(std::abs(lo[size_t(t)])), double(std::abs(hi[size_t(t)]))});
    }
  im.pad = float(1e-6 * extent);

  im.device = rtcNewDevice(nullptr);
  if (!im.device) throw InternalError("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(im.device, deviceError, &im.lastError);
  im.scene = rtcNewScene(im.device);
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, unsigned(im.tile.size()));
  rtcSetGeometryUserData(geom, &im);
  rtcSetGeometryBoundsFunction(geom, &Impl::bounds, nullptr);
  rtcSetGeometryIntersectFunction(geom, &Impl::intersect);
  rtcSetGeometryOccludedFunction(geom, &Impl::occluded);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(im.scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(im.scene);
  if (rtcGetDeviceError(im.device) != RTC_ERROR_NONE || !im.lastError.empty())
    throw InternalError("Embree: cannot build the surface's scene: " + im.lastError);
}

SurfaceScene::~SurfaceScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

size_t SurfaceScene::tiles() const {
  return impl_->tile.size();
}

namespace {

RTCRay embreeRay(const RayContext& c) {
  RTCRay r{};
  r.org_x = float(c.o.x), r.org_y = float(c.o.y), r.org_z = float(c.o.z);
  r.dir_x = float(c.d.x), r.dir_y = float(c.d.y), r.dir_z = float(c.d.z);
  r.tnear = std::max(0.0f, floatBelow(c.tNear));
  r.tfar = std::isfinite(c.tFar) ? floatAbove(c.tFar) : std::numeric_limits<float>::infinity();
  r.mask = ~0u;
  return r;
}

}  // namespace

PatchHit SurfaceScene::intersect(const Vec3& o, const Vec3& d, double tNear, double tFar) const {
  RayContext c;
  rtcInitIntersectContext(&c.embree);
  c.o = o, c.d = d, c.tNear = tNear, c.tFar = tFar;
  RTCRayHit rh{};
  rh.ray = embreeRay(c);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &c.embree, &rh);
  return c.hit;
}

bool SurfaceScene::occluded(const Vec3& o, const Vec3& d, double tNear, double tFar) const {
  RayContext c;
  rtcInitIntersectContext(&c.embree);
  c.o = o, c.d = d, c.tNear = tNear, c.tFar = tFar;
  RTCRay r = embreeRay(c);
  rtcOccluded1(impl_->scene, &c.embree, &r);
  return c.occluded;
}

}  // namespace scallop
