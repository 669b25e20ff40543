#include "app/checks/state_fingerprint.h"

#include <cstdio>
#include <cstring>
#include <span>

#include "app/runner/metrics_report.h"
#include "physics/core/byte_hash.h"

namespace pba::app {
namespace {

class HashingDraw final : public DebugDraw {
 public:
  ByteHash hash;

  void point(const Vec3& p, float size, const Color& c) override {
    tag(1);
    add(p);
    add(size);
    add(c);
  }
  void line(const Vec3& a, const Vec3& b, const Color& c) override {
    tag(2);
    add(a);
    add(b);
    add(c);
  }
  void arrow(const Vec3& a, const Vec3& b, const Color& c) override {
    tag(3);
    add(a);
    add(b);
    add(c);
  }
  void sphere(const Vec3& center, Real r, const Color& c) override {
    tag(4);
    add(center);
    add(r);
    add(c);
  }
  void box(const Vec3& center, const Vec3& half, const Quat& q, const Color& c) override {
    tag(5);
    add(center);
    add(half);
    add(q.w);
    add(q.x);
    add(q.y);
    add(q.z);
    add(c);
  }
  void capsule(const Vec3& a, const Vec3& b, Real r, const Color& c) override {
    tag(6);
    add(a);
    add(b);
    add(r);
    add(c);
  }
  void text(const Vec3& p, std::string_view, const Color&) override {
    tag(7);
    add(p);
  }
  void triangles(std::span<const Vec3> positions, std::span<const Vec3> normals, std::span<const std::uint32_t> indices,
                 const Color& c) override {
    tag(8);
    for (const Vec3& p : positions) add(p);
    for (const Vec3& n : normals) add(n);
    bytes(indices.data(), indices.size_bytes());
    add(c);
  }

 private:
  void bytes(const void* data, std::size_t n) { hash.bytes(data, n); }
  void tag(unsigned char t) { hash.add(t); }
  template <typename T>
  void add(const T& value) {
    hash.add(value);
  }
  void add(const Color& c) {
    add(c.r);
    add(c.g);
    add(c.b);
    add(c.a);
  }
};

}  // namespace

std::uint64_t drawHash(const Scene& scene) {
  HashingDraw draw;
  scene.draw(draw);
  return draw.hash.value();
}

nlohmann::json stateFingerprint(const SceneRunner& runner) {
  char hex[24];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(drawHash(runner.scene())));
  return {{"steps", runner.steps()},
          {"sim_time_s", runner.simTime()},
          {"draw_hash", hex},
          {"metrics", withoutTimings(runner.scene().metrics())}};
}

}  // namespace pba::app
