#include "embree_scene.h"

#include <cmath>

namespace edgefit {
namespace scanner_internal {

EmbreeScene::~EmbreeScene() {
  if (scene_ != nullptr) rtcReleaseScene(scene_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

void EmbreeScene::OnError(void* user, RTCError code, const char* message) {
  auto* self = static_cast<EmbreeScene*>(user);
  std::lock_guard<std::mutex> lock(self->error_mutex_);
  if (self->error_.empty()) {
    self->error_ = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                   (message != nullptr ? message : "(no message)");
  }
}

Status EmbreeScene::TakeError(const std::string& context) {
  std::lock_guard<std::mutex> lock(error_mutex_);
  if (error_.empty() && device_ != nullptr) {
    const RTCError code = rtcGetDeviceError(device_);
    if (code != RTC_ERROR_NONE) error_ = "Embree error " + std::to_string(static_cast<int>(code));
  }
  if (error_.empty()) return Status::Ok();
  Status status = Status::Error("virtual scanner: " + context + ": " + error_);
  error_.clear();
  return status;
}

Status EmbreeScene::Build(const Scene& scene, bool robust) {
  if (device_ != nullptr) return Status::Error("virtual scanner: Embree scene built twice");
  device_ = rtcNewDevice("verbose=0");
  if (device_ == nullptr) {
    return Status::Error("virtual scanner: cannot create an Embree device (error " +
                         std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  }
  rtcSetDeviceErrorFunction(device_, &EmbreeScene::OnError, this);
  scene_ = rtcNewScene(device_);
  if (scene_ == nullptr) return TakeError("new scene");
  rtcSetSceneFlags(scene_, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

  for (size_t id = 0; id < scene.meshes.size(); ++id) {
    const TriangleMesh& mesh = scene.meshes[id].mesh_world;
    if (mesh.triangles.empty()) continue;
    const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
    for (const Eigen::Vector3i& t : mesh.triangles) {
      for (int k = 0; k < 3; ++k) {
        if (t[k] < 0 || static_cast<size_t>(t[k]) >= nv) {
          return Status::Error("virtual scanner: scene mesh " + std::to_string(id) + " (" +
                               scene.meshes[id].kind + "): vertex index out of range");
        }
      }
    }
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (geometry == nullptr) return TakeError("new geometry");
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
    if (vertices == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      return TakeError("geometry buffers");
    }
    for (size_t v = 0; v < nv; ++v) {
      const Eigen::Vector3d& p = mesh.vertices[v];
      if (!p.allFinite()) {
        rtcReleaseGeometry(geometry);
        return Status::Error("virtual scanner: scene mesh " + std::to_string(id) + " (" +
                             scene.meshes[id].kind + "): non-finite vertex");
      }
      for (int k = 0; k < 3; ++k) vertices[3 * v + k] = static_cast<float>(p[k]);
    }
    for (size_t t = 0; t < nt; ++t) {
      for (int k = 0; k < 3; ++k) indices[3 * t + k] = static_cast<unsigned>(mesh.triangles[t][k]);
    }
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geometry);
    // geomID = mesh index, so a hit maps straight back to its SceneMesh.
    rtcAttachGeometryByID(scene_, geometry, static_cast<unsigned>(id));
    rtcReleaseGeometry(geometry);
    triangle_count_ += nt;
    EDGEFIT_RETURN_IF_ERROR(TakeError("scene mesh " + std::to_string(id)));
  }
  if (triangle_count_ == 0) return Status::Error("virtual scanner: the scene has no triangles");
  rtcCommitScene(scene_);
  return TakeError("scene commit");
}

}  // namespace scanner_internal
}  // namespace edgefit
