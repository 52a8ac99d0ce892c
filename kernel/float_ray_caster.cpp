#include "kernel/float_ray_caster.hpp"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace exactvis {

namespace {

// The intersect context extended with the triangles to ignore (Embree passes it to the filter function).
struct IgnoreContext {
  RTCIntersectContext base;  // must be first: Embree sees a pointer to it
  std::span<const std::int64_t> ignore;
  const std::vector<std::int64_t>* primitive_to_index = nullptr;
};

void ignore_filter(const RTCFilterFunctionNArguments* args) {
  const auto* ctx = reinterpret_cast<const IgnoreContext*>(args->context);
  if (ctx->ignore.empty()) return;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const std::int64_t index = (*ctx->primitive_to_index)[prim];
    for (std::int64_t skip : ctx->ignore) {
      if (skip == index) {
        args->valid[i] = 0;  // reject this hit; traversal goes on
        break;
      }
    }
  }
}

bool float_representable(double x) {
  return std::isfinite(x) && std::fabs(x) <= static_cast<double>(std::numeric_limits<float>::max());
}

RTCRay make_ray(const glm::vec3& o, const glm::vec3& d, float t_near, float t_far) {
  RTCRay ray{};
  ray.org_x = o.x;
  ray.org_y = o.y;
  ray.org_z = o.z;
  ray.dir_x = d.x;
  ray.dir_y = d.y;
  ray.dir_z = d.z;
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  ray.time = 0;
  return ray;
}

}  // namespace

struct FloatRayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::int64_t> primitive_to_index;  // Embree primitive id -> index into Scene::triangles
  std::int64_t skipped = 0;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

FloatRayCaster::FloatRayCaster(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.device = rtcNewDevice(nullptr);
  if (!im.device) throw std::runtime_error("Embree: cannot create a device (error " +
                                           std::to_string(rtcGetDeviceError(nullptr)) + ")");
  im.scene = rtcNewScene(im.device);
  rtcSetSceneBuildQuality(im.scene, RTC_BUILD_QUALITY_HIGH);
  // Robust traversal: no triangle is lost to aggressive culling in the BVH (hits are still only proposals).
  rtcSetSceneFlags(im.scene, RTC_SCENE_FLAG_ROBUST);

  std::vector<std::int64_t> kept;
  kept.reserve(scene.triangles.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      const Point3& p = scene.corner(scene.triangles[i], k);
      ok = float_representable(p.x) && float_representable(p.y) && float_representable(p.z);
    }
    if (ok) kept.push_back(static_cast<std::int64_t>(i));
    else ++im.skipped;
  }
  im.primitive_to_index = kept;
  if (!kept.empty()) {
    RTCGeometry geom = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* verts = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), 3 * kept.size()));
    auto* tris = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                3 * sizeof(unsigned), kept.size()));
    if (!verts || !tris) {
      rtcReleaseGeometry(geom);
      throw std::runtime_error("Embree: cannot allocate the geometry buffers");
    }
    // Every triangle gets its own three vertices: the BVH does not need the scene's sharing.
    for (std::size_t j = 0; j < kept.size(); ++j) {
      const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(kept[j])];
      for (int k = 0; k < 3; ++k) {
        const Point3& p = scene.corner(t, k);
        verts[9 * j + 3 * k + 0] = static_cast<float>(p.x);
        verts[9 * j + 3 * k + 1] = static_cast<float>(p.y);
        verts[9 * j + 3 * k + 2] = static_cast<float>(p.z);
        tris[3 * j + k] = static_cast<unsigned>(3 * j + k);
      }
    }
    rtcSetGeometryIntersectFilterFunction(geom, ignore_filter);
    rtcSetGeometryOccludedFilterFunction(geom, ignore_filter);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(im.scene, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(im.scene);
}

FloatRayCaster::~FloatRayCaster() = default;

FloatRayCaster::Hit FloatRayCaster::first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                                              float t_far, std::span<const std::int64_t> ignore) const {
  IgnoreContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.ignore = ignore;
  ctx.primitive_to_index = &impl_->primitive_to_index;
  RTCRayHit rh{};
  rh.ray = make_ray(origin, direction, t_near, t_far);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &ctx.base, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.triangle_index = impl_->primitive_to_index[rh.hit.primID];
  hit.t = rh.ray.tfar;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return hit;
}

bool FloatRayCaster::occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near, float t_far,
                              std::span<const std::int64_t> ignore) const {
  IgnoreContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.ignore = ignore;
  ctx.primitive_to_index = &impl_->primitive_to_index;
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(impl_->scene, &ctx.base, &ray);
  // Embree sets tfar to -inf when the ray is occluded.
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

std::int64_t FloatRayCaster::size() const { return static_cast<std::int64_t>(impl_->primitive_to_index.size()); }
std::int64_t FloatRayCaster::skipped() const { return impl_->skipped; }

}  // namespace exactvis
