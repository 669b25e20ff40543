#pragma once
// The scene interface every lab implements (docs/architecture.md §3). A scene owns its simulation state and
// steps it with a fixed dt handed in by the runner (never wall-clock time). The same object runs
// headless (tests, benchmarks, --headless) and in the window.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/params.h"
#include "app/runner/scene_state.h"
#include "physics/collision/ray.h"
#include "physics/core/debug_draw.h"
#include "physics/core/types.h"

namespace pba::app {

/// The share of |energy| a passive scene's energy may rise by before the guard pauses it (Scene::energyGainBound).
inline constexpr Real kPassiveEnergySlack = 0.05;
/// [J] The smallest energy scale of the guard (a scene at rest at zero energy still gets a bound).
inline constexpr Real kMinEnergyScale = 1e-3;

using Ray = pba::Ray;  ///< e.g. from the cursor through the scene

/// What a scene reports when a ray hits one of its draggable objects.
struct PickHit {
  int handle = -1;      ///< the scene's own id of the object (particle index, body id, …)
  Real distance = 0.0;  ///< along the ray [m]
  Vec3 point{0.0};      ///< world hit point [m]
};

/// The hit of `ray` with a sphere, reported as object `handle`: the usual pick() of a ball.
std::optional<PickHit> pickSphere(const Ray& ray, const Vec3& center, Real radius, int handle);

/// A named preset (keys 1–9): parameter values applied before a reset. A preset sets every parameter:
/// those it does not name take the scene's defaults (app::presetParams), so a key gives the same
/// setup whatever was pressed before.
struct Preset {
  std::string name;
  nlohmann::json params;  ///< same shape as a scene file's "params"
};

/// An object the left mouse button can drag, where it is now (Scene::dragHandles).
struct DragHandle {
  int handle = -1;     ///< the id pick() reports for it
  Vec3 position{0.0};  ///< [m] world
};

/// One line of a scene's legend: a colour swatch and what that colour shows.
struct LegendEntry {
  Color color;
  std::string text;
};

/// A camera a scene asks for when fitting its drawing's bounding sphere frames it poorly (a flat figure
/// facing the camera, a tall fountain): look at `target` from `distance` at `yaw` and `pitch` [rad].
struct CameraView {
  Vec3 target{0.0};    ///< [m]
  Real distance = 10;  ///< [m]
  Real yaw = 0.6;      ///< [rad] about +y (the framework's default camera yaw)
  Real pitch = 0.45;   ///< [rad] above the horizon
};

/// One joint of a scene's skeleton where it is now (Scene::jointPositions, --pose-json).
struct NamedPoint {
  std::string name;
  Vec3 position{0.0};  ///< [m] world
};

/// A rectangle of the window in pixels, y down (ImGui's convention).
struct ScreenRect {
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
};

class Scene {
 public:
  Scene() = default;
  virtual ~Scene() = default;

  /// One sentence: what to look at in this scene.
  virtual std::string description() const = 0;
  /// Checks what the parameters name before the scene is used (e.g. loads the model file of a text
  /// parameter). The command line turns an error into exit code 2; a scene file or preset with an
  /// error is not applied. The message names the file and field: "skeleton: arm.bvh: ...".
  virtual Status validate() { return Status::success(); }
  /// Rebuilds the simulation state from the current parameters.
  virtual void reset() = 0;
  /// Advances the simulation by dt seconds (fixed step).
  virtual void step(Real dt) = 0;
  /// Draws the current state.
  virtual void draw(DebugDraw& draw) const = 0;
  /// Live measurements (energy, residual, …): a flat JSON object of numbers, strings and booleans.
  virtual nlohmann::json metrics() const = 0;
  /// Extra ImGui widgets beyond the automatic parameter panel (optional; window mode only).
  virtual void ui() {}
  /// True while the scene wants a window of its own in the right-hand column (the IK lab's Jacobian
  /// heat map): the framework then reserves that column and frames the camera beside it.
  virtual bool wantsOverlay() const { return false; }
  /// Draws that window inside `column` [pixels] (window mode only, while the panels are shown).
  virtual void overlayUi(const ScreenRect& /*column*/) {}

  /// The view to frame this scene with (F, reset, start); empty: fit the drawn bounds. The framework
  /// still shifts it right of the control panel, but not up for the plots (the scene leaves them room).
  virtual std::optional<CameraView> preferredView() const { return std::nullopt; }
  /// The time step this scene is designed for [s].
  virtual Real defaultDt() const { return 1.0 / 120.0; }
  /// True for a scene built to load the machine (a benchmark or stress scene: Bullet's 3000 boxes, a
  /// thousand-body pile): `./pba bench` lists its time but does not hold it to the budget of 2 ms of
  /// physics per frame that every other scene keeps at its defaults (docs/architecture.md §8). The
  /// metrics report carries it as "heavy".
  virtual bool heavy() const { return false; }
  /// Empty when the state is finite; otherwise names what is not ("ball velocity is NaN").
  virtual std::optional<std::string> nonFiniteState() const = 0;
  /// Empty unless the scene's solver says it has diverged while the state is still finite (the cloth's
  /// speed limit): the guard then pauses as for a runaway, naming what this returns.
  virtual std::optional<std::string> divergedState() const { return std::nullopt; }
  /// Total energy [J] for the runaway guard, when the scene has one.
  virtual std::optional<Real> energy() const { return std::nullopt; }
  /// How much energy [J] the scene may gain over `reference`, its energy() at reset or at the user's last
  /// input (drag, nudge, scene key, parameter edit), before the guard pauses it (issue 35). A passive scene
  /// never gains energy: the default allows only a numerical slack of kPassiveEnergySlack of |reference|
  /// (at least 1 mJ), which integrators' bounded energy oscillation stays within. A scene driven by a motor,
  /// wind or an emitter states its own bound; nullopt leaves only the runaway factor of |E| at reset.
  virtual std::optional<Real> energyGainBound(Real reference) const;
  /// Metrics plotted over time when the user has not chosen any (e.g. {"energy_J"}).
  virtual std::vector<std::string> defaultPlots() const { return {}; }
  /// Keys 1–9.
  virtual std::vector<Preset> presets() const { return {}; }

  /// Picking and dragging through the scene interface (left mouse button).
  virtual std::optional<PickHit> pick(const Ray&) const { return std::nullopt; }
  virtual void drag(int /*handle*/, const Vec3& /*target*/) {}
  virtual void release(int /*handle*/) {}
  /// Keyboard nudge (arrow keys, PageUp/PageDown; app/window/target_nudge.h): moves the scene's current
  /// target (the goal last picked, …) by `delta` [m, world]. False when there is nothing to nudge.
  virtual bool nudge(const Vec3& /*delta*/) { return false; }
  /// A scene's own key (an upper-case letter registered with PBA_REGISTER_LAB_KEY, so that the F1 help
  /// and --help list it). True when the scene acted on it.
  virtual bool keyPressed(char /*key*/) { return false; }
  /// Recomputes what follows from the scene's inputs without advancing time (an IK pose after its goal
  /// moved). The runner calls it after every drag and nudge while the scene is paused, so a paused
  /// scene shows the effect of any goal change at once, whatever moved it. Default: nothing.
  virtual void refresh() {}
  /// The draggable objects and their positions (at most a few dozen; a large system lists a sample).
  /// The window's UI status reports them, so tests can find an object on screen and check a drag.
  virtual std::vector<DragHandle> dragHandles() const { return {}; }
  /// What the colours of the picture mean. The window shows it in a free corner, also while Tab hides
  /// the panels, since it explains the picture rather than controlling it.
  virtual std::vector<LegendEntry> legend() const { return {}; }
  /// Every joint of the scene's skeleton by name, at its world position now; empty when the scene has
  /// no skeleton. The runner writes them to --pose-json FILE when the run ends (app/runner/pose_json.h).
  virtual std::vector<NamedPoint> jointPositions() const { return {}; }
  /// The goals the skeleton reaches for (IK), each named after the point of jointPositions() that reaches
  /// for it; written beside the joints by --pose-json. Default: none.
  virtual std::vector<NamedPoint> goalPositions() const { return {}; }
  /// Length [m] of one nudge; 0 lets the runner choose 2 % of the scene's drawn size.
  virtual Real nudgeStep() const { return 0.0; }

  /// A copy of the complete simulation state (rewind, A/B runs), or null for a scene made outside the
  /// registry. Every registered scene has one (scene_state.h): no code in the scene.
  std::unique_ptr<const SceneState> saveState() const { return stateOps_ ? stateOps_->save(*this) : nullptr; }
  /// Puts back a state saved from this scene (or one of its type): parameters, seed and simulation.
  /// False when the state belongs to another scene type.
  bool restoreState(const SceneState& state) { return stateOps_ && stateOps_->restore(*this, state); }
  /// Installed by the registry for scenes of its type T.
  void setStateOps(std::shared_ptr<const SceneStateOps> ops) { stateOps_ = std::move(ops); }

  Params& params() { return params_; }
  const Params& params() const { return params_; }
  /// Random seed for scenes with random content (set by the runner before reset()).
  void setSeed(std::uint64_t seed) { seed_ = seed; }
  std::uint64_t seed() const { return seed_; }

 protected:
  // Copies (the saved states) carry the seed but not the parameter table: its accessors point into the
  // object that declared them, so each scene keeps its own.
  Scene(const Scene& other) : seed_(other.seed_), stateOps_(other.stateOps_) {}
  Scene& operator=(const Scene& other) {
    seed_ = other.seed_;
    return *this;
  }

  Params params_;

 private:
  std::uint64_t seed_ = 1;
  std::shared_ptr<const SceneStateOps> stateOps_;
};

}  // namespace pba::app
