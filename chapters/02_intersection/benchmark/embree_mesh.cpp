#include "embree_mesh.hpp"

#include <embree3/rtcore.h>

#include <atomic>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <sys/types.h>

namespace rt {

const char* embree_version() {
    return RTC_VERSION_STRING;
}

struct EmbreeMesh::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::atomic<long long> bytes{0};
};

namespace {

bool count_bytes(void* user, ssize_t bytes, bool /*post*/) {
    static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
    return true;
}

}  // namespace

EmbreeMesh::EmbreeMesh(const MeshShape& mesh, bool robust) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("Embree: rtcNewDevice failed");
    rtcSetDeviceMemoryMonitorFunction(impl_->device, count_bytes, &impl_->bytes);
    impl_->scene = rtcNewScene(impl_->device);
    if (robust) rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                 mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) vertices[3 * i + std::size_t(k)] = float(mesh.positions[i][k]);
    }
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                   RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                   mesh.triangles.size()));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (std::size_t k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(impl_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(impl_->scene);
}

EmbreeMesh::~EmbreeMesh() {
    rtcReleaseScene(impl_->scene);
    rtcReleaseDevice(impl_->device);
}

namespace {

void set_ray(RTCRay& r, const Ray& ray, Real t_max) {
    r.org_x = float(ray.origin.x);
    r.org_y = float(ray.origin.y);
    r.org_z = float(ray.origin.z);
    r.dir_x = float(ray.direction.x);
    r.dir_y = float(ray.direction.y);
    r.dir_z = float(ray.direction.z);
    r.tnear = 0;
    r.tfar = float(t_max);
    r.time = 0;
    r.mask = std::numeric_limits<unsigned>::max();
    r.id = 0;
    r.flags = 0;
}

}  // namespace

std::optional<NearestHit> EmbreeMesh::intersect(const Ray& ray, Real t_max) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query;
    set_ray(query.ray, ray, t_max);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return NearestHit{query.ray.tfar, query.hit.primID, {query.hit.u, query.hit.v}};
}

bool EmbreeMesh::occluded(const Ray& ray, Real t_max) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay query;
    set_ray(query, ray, t_max);
    rtcOccluded1(impl_->scene, &context, &query);
    return query.tfar < 0;  // Embree sets tfar to −∞ when something is hit
}

std::size_t EmbreeMesh::bytes() const {
    return std::size_t(impl_->bytes.load());
}

}  // namespace rt
