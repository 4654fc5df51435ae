// ray_scene: Embree 3 device and scene of the shadow casters (see ray_scene.h).
#include "ray_scene.h"

#include "mesh.h"

#if SHADOWLAB_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#include <limits>
#include <stdexcept>
#include <string>

namespace sl {

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayScene::RayScene(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device)
        throw std::runtime_error("Embree: rtcNewDevice failed (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    impl_->scene = rtcNewScene(impl_->device);
    // Robust traversal: rays that graze an edge shared by two triangles must not slip through.
    rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
    Bounds all;
    for (const Object& object : scene.objects) {
        if (!object.castsShadows) continue;
        const Mesh mesh = buildMesh(object, scene);
        if (mesh.indices.empty()) continue;
        const glm::mat4 model = objectToWorld(object);
        RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
            mesh.positions.size()));
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            // The same product scene.vert computes: uModel * vec4(aPosition, 1).
            const glm::vec4 w = model * glm::vec4(mesh.positions[i], 1.0f);
            v[3 * i] = w.x, v[3 * i + 1] = w.y, v[3 * i + 2] = w.z;
            all.add(glm::vec3(w));
        }
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
            mesh.indices.size() / 3));
        for (size_t i = 0; i < mesh.indices.size(); ++i) idx[i] = mesh.indices[i];
        rtcCommitGeometry(geom);
        rtcAttachGeometry(impl_->scene, geom);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(impl_->scene);
    if (!all.empty()) diagonal_ = glm::length(all.hi - all.lo);
    if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE)
        throw std::runtime_error(scene.path + ": Embree could not build the scene");
}

RayScene::~RayScene() = default;

bool RayScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float tnear,
                        float tfar) const {
    RTCRay ray{};
    ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
    ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
    ray.tnear = tnear;
    ray.tfar = tfar;
    ray.mask = std::numeric_limits<unsigned>::max();
    ray.flags = 0;
    ray.time = 0.0f;
#if SHADOWLAB_EMBREE_MAJOR >= 4
    rtcOccluded1(impl_->scene, &ray);  // Embree 4: the context became optional arguments
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(impl_->scene, &context, &ray);
#endif
    return ray.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
}

}  // namespace sl
