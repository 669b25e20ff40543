#include "anim_scene.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace pba::lab {
namespace {

/// A key pressed this frame. ImGui 1.87 takes the named key itself; 1.86 (Debian 12's) an index
/// that GetKeyIndex maps it to (removed in 1.91).
bool imguiKeyPressed(ImGuiKey key) {
#if IMGUI_VERSION_NUM >= 18700
  return ImGui::IsKeyPressed(key);
#else
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
#endif
}

}  // namespace

AnimScene::AnimScene() {
  params_.real("speed", &speed_, 0.0, 3.0, "",
               "Playback speed (1 = real time). The timeline keys move the clock by frames of 1/30 s.");
  params_.flag("loop", &loop_, "Loop the clip; off, the clock stops at its end.");
}

std::vector<app::NamedPoint> AnimScene::jointPositions() const {
  std::vector<app::NamedPoint> out;
  for (size_t j = 0; j < world_.size() && j < skeleton_.names.size(); ++j)
    out.push_back({skeleton_.names[j], world_[j].position});
  return out;
}

void AnimScene::resetClock() {
  time_ = 0.0;
  previous_.clear();
  maxVelocity_ = 0.0;
  evaluate();
}

void AnimScene::seek(Real t) {
  const Real d = duration();
  time_ = std::clamp(t, 0.0, d);
  previous_.clear();
  evaluate();
}

void AnimScene::step(Real dt) {
  const Real d = duration();
  time_ += speed_ * dt;
  if (time_ > d) {
    time_ = loop_ && d > 0.0 ? std::fmod(time_, d) : d;
    previous_.clear();  // the loop jumps back: no velocity across it
  }
  evaluate();
  simulate(dt);
  measureVelocity(dt);
}

void AnimScene::measureVelocity(Real dt) {
  const bool comparable = previous_.size() == world_.size();
  maxVelocity_ = 0.0;
  for (size_t j = 0; comparable && j < world_.size(); ++j)
    maxVelocity_ = std::max(maxVelocity_, glm::length(world_[j].position - previous_[j]) / dt);
  previous_.resize(world_.size());
  for (size_t j = 0; j < world_.size(); ++j) previous_[j] = world_[j].position;
}

nlohmann::json AnimScene::metrics() const {
  nlohmann::json m;
  m["time_s"] = time_;
  m["keys"] = keyTimes().size();
  m["clip_frames"] = clipFrames_;
  m["joints"] = skeleton_.size();
  m["max_velocity_m_s"] = maxVelocity_;
  m["continuity_error"] = continuity_;
  m["pendulum_energy_J"] = pendulumEnergy_;
  addMetrics(m);
  return m;
}

std::optional<std::string> AnimScene::nonFiniteState() const {
  for (size_t j = 0; j < world_.size(); ++j)
    if (!isFinite(world_[j].position)) return "joint " + skeleton_.names[j] + " position is not finite";
  return std::nullopt;
}

Real AnimScene::continuityError(const an::Channel<Vec3>& c) {
  Real worst = 0.0;
  const Real e = 1e-7;  // [s] either side of a key; a C¹ curve changes by O(e) there
  for (int k = 1; k + 1 < c.size(); ++k) {
    const Real t = c.time(k);
    worst = std::max(worst, glm::length(c.valueAt(t + e) - c.valueAt(t - e)));
    worst = std::max(worst, glm::length(c.velocityAt(t + e) - c.velocityAt(t - e)));
  }
  return worst;
}

std::optional<app::PickHit> AnimScene::pickJoint(const app::Ray& ray, Real radius) const {
  std::optional<app::PickHit> best;
  for (size_t j = 0; j < world_.size(); ++j) {
    const std::optional<app::PickHit> h = app::pickSphere(ray, world_[j].position, radius, static_cast<int>(j));
    if (h && (!best || h->distance < best->distance)) best = h;
  }
  return best;
}

void AnimScene::drawCharacter(DebugDraw& d, const an::Skeleton& s, const std::vector<an::JointWorld>& world,
                              float alpha) const {
  auto side = [&](size_t j) {
    const std::string& n = s.names[j];
    Color c = n.rfind("Left", 0) == 0 || n.rfind("l", 0) == 0    ? colors::kBlue
              : n.rfind("Right", 0) == 0 || n.rfind("r", 0) == 0 ? colors::kOrange
                                                                 : colors::kGrey;
    c.a = alpha;
    return c;
  };
  Real height = 0.0;
  for (const an::JointWorld& w : world) height = std::max(height, w.position.y);
  const Real r = std::clamp(0.02 * height, 0.01, 0.05);  // [m] bone radius for a 1.7 m character: 3.4 cm
  for (size_t j = 1; j < world.size() && j < s.names.size(); ++j) {
    const int p = s.parents[j];
    if (p < 0) continue;
    const Vec3 a = world[static_cast<size_t>(p)].position, b = world[j].position;
    if (glm::length(b - a) > 1e-6) d.capsule(a, b, r, side(j));
  }
  Color joint = colors::kDark;
  joint.a = alpha;
  for (size_t j = 0; j < world.size(); ++j) d.sphere(world[j].position, 1.25 * r, joint);
  const int head = s.find("Head");
  if (head >= 0)
    d.sphere(toWorld(world[static_cast<size_t>(head)], Vec3(0.0, 0.09, 0.0)), 0.1, Color{0.93f, 0.76f, 0.62f, alpha});
}

void AnimScene::ui() {
  timelineKeys();
  timelineBar();
  sceneUi();
}

void AnimScene::timelineKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  const Real frame = 1.0 / kTimelineFrameRate;
  const std::vector<Real> keys = keyTimes();
  auto jumpKey = [&](int dir) {
    Real best = dir > 0 ? duration() : 0.0;
    for (Real k : keys)
      if ((dir > 0 && k > time_ + 1e-9 && k < best) || (dir < 0 && k < time_ - 1e-9 && k > best)) best = k;
    seek(best);
  };
  for (int dir : {-1, +1}) {
    if (!imguiKeyPressed(dir < 0 ? ImGuiKey_LeftArrow : ImGuiKey_RightArrow)) continue;
    if (io.KeyAlt)
      jumpKey(dir);
    else
      seek(time_ + dir * (io.KeyShift ? 10.0 : 1.0) * frame);
  }
  if (imguiKeyPressed(ImGuiKey_Home)) seek(0.0);
  if (imguiKeyPressed(ImGuiKey_End)) seek(duration());
  if (imguiKeyPressed(ImGuiKey_Delete) && selectedKey_ >= 0 && deleteKey(selectedKey_)) selectedKey_ = -1;
}

void AnimScene::timelineBar() {
  if (!ImGui::CollapsingHeader("Timeline", ImGuiTreeNodeFlags_DefaultOpen)) return;
  float t = static_cast<float>(time_);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##time", &t, 0.0f, static_cast<float>(duration()), "%.3f s")) seek(t);
  // Key markers under the slider: a tick per key, the selected one larger; click selects and seeks.
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(220, 222, 226, 255));
  const std::vector<Real> keys = keyTimes();
  const Real d = std::max(duration(), 1e-9);
  for (size_t k = 0; k < keys.size(); ++k) {
    const float x = origin.x + width * static_cast<float>(keys[k] / d);
    const bool selected = static_cast<int>(k) == selectedKey_;
    draw->AddRectFilled(ImVec2(x - (selected ? 3.0f : 1.5f), origin.y),
                        ImVec2(x + (selected ? 3.0f : 1.5f), origin.y + height),
                        selected ? IM_COL32(220, 50, 45, 255) : IM_COL32(40, 42, 48, 255));
  }
  const float cursor = origin.x + width * static_cast<float>(time_ / d);
  draw->AddLine(ImVec2(cursor, origin.y - 2.0f), ImVec2(cursor, origin.y + height + 2.0f), IM_COL32(40, 105, 220, 255),
                2.0f);
  ImGui::InvisibleButton("##keys", ImVec2(width, height));
  if (ImGui::IsItemClicked() && !keys.empty()) {
    const Real clicked = d * (ImGui::GetIO().MousePos.x - origin.x) / width;
    size_t nearest = 0;
    for (size_t k = 1; k < keys.size(); ++k)
      if (std::abs(keys[k] - clicked) < std::abs(keys[nearest] - clicked)) nearest = k;
    selectedKey_ = static_cast<int>(nearest);
    seek(keys[nearest]);
  }
  ImGui::TextDisabled("%zu keys  ·  ←/→ frame, Shift ×10, Alt key, Home/End, Del key", keys.size());
}

}  // namespace pba::lab
