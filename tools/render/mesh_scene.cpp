#include "tools/render/mesh_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/internal_error.h"

namespace scallop {

namespace {

void deviceError(void* user, RTCError, const char* message) {
  *static_cast<std::string*>(user) = message ? message : "unknown Embree error";
}

RTCRay embreeRay(const Vec3& o, const Vec3& d, double tNear, double tFar) {
  RTCRay r{};
  r.org_x = float(o.x), r.org_y = float(o.y), r.org_z = float(o.z);
  r.dir_x = float(d.x), r.dir_y = float(d.y), r.dir_z = float(d.z);
  r.tnear = float(std::max(0.0, tNear));
  r.tfar = std::isfinite(tFar) ? float(tFar) : std::numeric_limits<float>::infinity();
  r.mask = ~0u;
  return r;
}

}  // namespace

struct MeshScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::string lastError;
};

MeshScene::MeshScene(const TriangleMesh& mesh) : impl_(new Impl) {
  Impl& im = *impl_;
  im.device = rtcNewDevice("threads=1");
  if (!im.device) throw InternalError("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(im.device, deviceError, &im.lastError);
  im.scene = rtcNewScene(im.device);
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                           RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                           mesh.triangles.size()));
  if (!v || !f) throw InternalError("Embree: cannot allocate the mesh buffers: " + im.lastError);
  for (size_t k = 0; k < mesh.vertices.size(); ++k)
    v[3 * k] = float(mesh.vertices[k].x), v[3 * k + 1] = float(mesh.vertices[k].y),
          v[3 * k + 2] = float(mesh.vertices[k].z);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) f[3 * t + size_t(c)] = mesh.triangles[t][size_t(c)];
  rtcCommitGeometry(geom);
  rtcAttachGeometry(im.scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(im.scene);
  if (rtcGetDeviceError(im.device) != RTC_ERROR_NONE || !im.lastError.empty())
    throw InternalError("Embree: cannot build the mesh's scene: " + im.lastError);
}

MeshScene::~MeshScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

MeshHit MeshScene::intersect(const Vec3& o, const Vec3& d, double tNear, double tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = embreeRay(o, d, tNear, tFar);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  MeshHit h;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
  h.t = rh.ray.tfar, h.triangle = rh.hit.primID, h.b1 = rh.hit.u, h.b2 = rh.hit.v;
  return h;
}

bool MeshScene::occluded(const Vec3& o, const Vec3& d, double tNear, double tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = embreeRay(o, d, tNear, tFar);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0;
}

}  // namespace scallop
