// The Embree side of scallop, walked through once (after Embree's minimal tutorial):
// a device, one scene, one user geometry whose primitives are the moves' boxes, a bounds
// callback that hands Embree those boxes (rounded outwards to float), and an intersect
// callback that gathers every box a ray meets and accepts none, so that the ray runs its
// whole length. (The z-map's culling scene answers such queries with its tile grid
// instead: raycast/swept_scene.h.)
#include "analysis/move_line_index.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace scallop {

namespace {

// A ray's context: Embree hands it to the intersect callback, which gathers every box
// the traversal reaches and accepts none, so that the ray runs its whole length.
struct GatherContext {
  RTCIntersectContext embree;
  std::vector<uint32_t>* ids;
};

void deviceError(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  *last = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

}  // namespace

struct MoveLineIndex::Impl {
  std::vector<Box3> boxes;  // grown by the slack
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string lastError;
  double slack = 0;

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const Box3& b = static_cast<const Impl*>(args->geometryUserPtr)->boxes[args->primID];
    RTCBounds* o = args->bounds_o;
    // Rounded outwards: the float box holds the double one.
    o->lower_x = std::nextafter(float(b.min.x), -HUGE_VALF);
    o->lower_y = std::nextafter(float(b.min.y), -HUGE_VALF);
    o->lower_z = std::nextafter(float(b.min.z), -HUGE_VALF);
    o->upper_x = std::nextafter(float(b.max.x), HUGE_VALF);
    o->upper_y = std::nextafter(float(b.max.y), HUGE_VALF);
    o->upper_z = std::nextafter(float(b.max.z), HUGE_VALF);
  }

  static void intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;  // single rays only (rtcIntersect1)
    reinterpret_cast<GatherContext*>(args->context)->ids->push_back(args->primID);
  }
};

MoveLineIndex::MoveLineIndex(const std::vector<Box3>& boxes, double slack)
    : impl_(std::make_unique<Impl>()) {
  impl_->slack = slack;
  impl_->boxes = boxes;
  for (Box3& b : impl_->boxes) {
    b.min = b.min - Vec3{slack, slack, slack};
    b.max = b.max + Vec3{slack, slack, slack};
  }
  if (impl_->boxes.empty()) return;
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(impl_->device, deviceError, &impl_->lastError);
  impl_->scene = rtcNewScene(impl_->device);
  // Robust traversal: a ray exactly on a box face must not slip through.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, unsigned(impl_->boxes.size()));
  rtcSetGeometryUserData(geom, impl_.get());
  rtcSetGeometryBoundsFunction(geom, Impl::bounds, impl_.get());
  rtcSetGeometryIntersectFunction(geom, Impl::intersect);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(impl_->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(impl_->scene);
  if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE || !impl_->lastError.empty())
    throw std::runtime_error(impl_->lastError.empty() ? "Embree: index build failed"
                                                      : impl_->lastError);
}

MoveLineIndex::~MoveLineIndex() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

void MoveLineIndex::boxesMeeting(const Vec3& p, const Vec3& n, double w0, double w1,
                                 std::vector<uint32_t>& ids) const {
  ids.clear();
  if (!impl_->scene) return;
  const double slack = impl_->slack;
  const Vec3 origin = p + n * (w0 - slack);
  GatherContext context;
  rtcInitIntersectContext(&context.embree);
  context.ids = &ids;
  RTCRayHit rh;
  rh.ray.org_x = float(origin.x), rh.ray.org_y = float(origin.y), rh.ray.org_z = float(origin.z);
  rh.ray.dir_x = float(n.x), rh.ray.dir_y = float(n.y), rh.ray.dir_z = float(n.z);
  rh.ray.tnear = 0;
  rh.ray.tfar = std::nextafter(float(w1 - w0 + 2 * slack), HUGE_VALF);
  rh.ray.time = 0;
  rh.ray.mask = ~0u;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context.embree, &rh);
  std::sort(ids.begin(), ids.end());
}

}  // namespace scallop
