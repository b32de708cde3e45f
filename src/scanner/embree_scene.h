// EmbreeScene (internal): an Embree 3 device and committed scene built from a
// Scene, one triangle geometry per SceneMesh with geomID = mesh index.
// Embree reports errors through a callback; they are collected and turned
// into a Status, never a crash.
#ifndef EDGEFIT_SRC_SCANNER_EMBREE_SCENE_H_
#define EDGEFIT_SRC_SCANNER_EMBREE_SCENE_H_

#include <embree3/rtcore.h>

#include <mutex>
#include <string>

#include "edgefit/core/status.h"
#include "edgefit/scene/scene.h"

namespace edgefit {
namespace scanner_internal {

class EmbreeScene {
 public:
  EmbreeScene() = default;
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Builds the BVH of `scene` (RTC_BUILD_QUALITY_HIGH; robust: RTC_SCENE_FLAG_ROBUST).
  Status Build(const Scene& scene, bool robust);

  RTCScene scene() const { return scene_; }
  size_t triangle_count() const { return triangle_count_; }

 private:
  static void OnError(void* user, RTCError code, const char* message);
  // The first error Embree reported since the last call, cleared.
  Status TakeError(const std::string& context);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  size_t triangle_count_ = 0;
  std::mutex error_mutex_;
  std::string error_;
};

}  // namespace scanner_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_SCANNER_EMBREE_SCENE_H_
