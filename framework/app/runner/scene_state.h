#pragma once
// Saving and restoring a scene's complete simulation state: the rewind history, A/B runs and the rewind
// tests (docs/architecture.md §3, "Rewind"). The registry gives every scene type T a copier that takes
// the whole object by T's copy constructor and puts it back by T's copy assignment, so a scene needs no
// code of its own as long as its members are values (vectors, structs, solvers). Scene's own copy skips
// the parameter table (its accessors point into the live object); the parameter values themselves are
// fields of T and travel with the state.
#include <cstddef>
#include <memory>

namespace pba::app {

class Scene;

/// An opaque copy of one scene's complete state.
class SceneState {
 public:
  virtual ~SceneState() = default;
  /// What the copy holds in memory [bytes]: the object and the heap it owns (measured at the copy).
  std::size_t bytes() const { return bytes_; }
  void setBytes(std::size_t bytes) { bytes_ = bytes; }

 private:
  std::size_t bytes_ = 0;
};

/// Bytes allocated from the heap right now: the sanitizer's count under ASan, glibc's mallinfo2
/// otherwise; 0 where neither is known (the state's size then counts the object alone).
std::size_t heapBytesInUse();

/// How states of one scene type are taken and put back (installed by the registry).
class SceneStateOps {
 public:
  virtual ~SceneStateOps() = default;
  virtual std::unique_ptr<const SceneState> save(const Scene& scene) const = 0;
  /// False when `state` was taken from a scene of another type.
  virtual bool restore(Scene& scene, const SceneState& state) const = 0;
};

template <typename T>
class CopiedSceneState final : public SceneState {
 public:
  explicit CopiedSceneState(const T& scene) : value(scene) {}
  T value;
};

template <typename T>
class CopySceneStateOps final : public SceneStateOps {
 public:
  std::unique_ptr<const SceneState> save(const Scene& scene) const override {
    const std::size_t before = heapBytesInUse();
    auto state = std::make_unique<CopiedSceneState<T>>(static_cast<const T&>(scene));
    const std::size_t after = heapBytesInUse();
    state->setBytes(after > before ? after - before : sizeof(CopiedSceneState<T>));
    return state;
  }
  bool restore(Scene& scene, const SceneState& state) const override {
    const auto* copy = dynamic_cast<const CopiedSceneState<T>*>(&state);
    if (!copy) return false;
    static_cast<T&>(scene) = copy->value;
    return true;
  }
};

}  // namespace pba::app
