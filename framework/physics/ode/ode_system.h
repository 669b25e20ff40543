#pragma once
// The ODE layer's half that knows the physics: a "state source" in the words of the Lobb notes
// ("Solver/state separation", after Witkin & Baraff's SIGGRAPH course notes). The solver
// (integrators.h) knows nothing about particles; it only sees
//   state length · get state · set state · derivative ṡ = f(s, t) · time.
//
// Glossary
//   s    state vector, s ∈ ℝᴺ                       (for particles: N = 6n, s = (x₁…xₙ, v₁…vₙ))
//   ṡ    its time derivative f(s, t)
//   q, v generalised positions and velocities of a second-order system, q̈ = M⁻¹ f(t, q, q̇)
//   M    diagonal mass matrix; M⁻¹ = 0 on a pinned coordinate
#include <cstddef>
#include <span>
#include <vector>

#include "physics/core/types.h"

namespace pba::ode {

/// A first-order initial value problem ṡ = f(s, t) (Lobb notes, "ODE view").
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  /// N, the length of the state vector.
  virtual std::size_t stateSize() const = 0;
  /// Copies the current state into out (size N).
  virtual void getState(std::span<Real> out) const = 0;
  /// Replaces the current state (size N).
  virtual void setState(std::span<const Real> state) = 0;
  /// ṡ = f(s, t) at an arbitrary state s. The notes evaluate the derivative of the *current* state;
  /// taking s as an argument lets the Runge–Kutta stages run without set/get round trips.
  virtual void derivative(Real t, std::span<const Real> state, std::span<Real> out) const = 0;
  /// The system's own storage of s, when it keeps the whole state as one array of stateSize() values
  /// (OwnedStateSystem does); empty when it does not (the default). The generic methods then advance
  /// the state where it lives instead of a copy of it (ode/step_helpers.h): getState() into this span
  /// and setState() from it must leave the state as it is (a system that lends its storage makes them
  /// copy nothing then).
  virtual std::span<Real> stateStorage() { return {}; }

  /// Simulated time [s]; integrators advance it by the step they take (the notes' "advance time").
  Real time() const { return time_; }
  void setTime(Real t) { time_ = t; }

 private:
  Real time_ = 0.0;
};

/// A mechanical system q̈ = M⁻¹ f(t, q, q̇): state s = (q, v) with v = q̇. Symplectic Euler, Verlet and
/// implicit Euler need this split; the generic methods see it as an OdeSystem.
class SecondOrderSystem : public OdeSystem {
 public:
  /// n, the number of generalised coordinates (3 per particle).
  virtual std::size_t dofCount() const = 0;
  /// Views of the system's own position and velocity storage (n values each). Integrators update them
  /// in place, so a second-order step copies nothing.
  virtual std::span<Real> positions() = 0;
  virtual std::span<const Real> positions() const = 0;
  virtual std::span<Real> velocities() = 0;
  virtual std::span<const Real> velocities() const = 0;
  /// M⁻¹ per coordinate [1/kg] (or 1/(kg·m²) for angles); 0 marks a pinned coordinate.
  virtual std::span<const Real> inverseMasses() const = 0;
  /// Generalised force f(t, q, v) [N] (or N·m) written to out (n values; overwrite, do not add).
  virtual void force(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const = 0;
  /// Directional derivative of the force: out = (∂f/∂q)·dq + (∂f/∂v)·dv. Implicit Euler uses it as the
  /// matrix-free Jacobian (Baraff & Witkin 1998 §5). The default takes central finite differences of
  /// force(); mass-spring systems override it with the analytic Jacobian. Not const: the default keeps
  /// its scratch in the system (each thread steps its own system).
  virtual void forceDifferential(Real t, std::span<const Real> q, std::span<const Real> v, std::span<const Real> dq,
                                 std::span<const Real> dv, std::span<Real> out);
  /// The 3×3 diagonal blocks of ∂f/∂q and ∂f/∂v, one per group of three coordinates (a particle:
  /// coordinates 3i…3i+2), written to dfdq and dfdv (dofCount()/3 each): implicit Euler's block-Jacobi
  /// preconditioner. Returns false when the system cannot give them (the default); implicit Euler then
  /// preconditions with the masses alone.
  virtual bool forceJacobianDiagonalBlocks(Real /*t*/, std::span<const Real> /*q*/, std::span<const Real> /*v*/,
                                           std::span<Mat3> /*dfdq*/, std::span<Mat3> /*dfdv*/) const {
    return false;
  }
  /// The size g of the groups of coordinates the force keeps apart, when it couples no coordinate with one
  /// outside its group (f of a group depends on t and that group's q and v alone): 1 for independent
  /// coordinates (the oscillators), 3 for particles under fields and drag without springs; 0 (the
  /// default) for a coupled system. Only 1 and 3 are supported. Then ∂f/∂q and ∂f/∂v are block diagonal
  /// and so is implicit Euler's matrix: it solves each g × g block directly (uncoupledForce) instead of
  /// running conjugate gradients.
  virtual int uncoupledGroupSize() const { return 0; }
  /// For an uncoupled system (uncoupledGroupSize() = g > 0): the force and the diagonal blocks of its
  /// Jacobians for the coordinates first … first + f.size() − 1 (first and f.size() multiples of g),
  /// read from the whole q and v: f (one value per coordinate), dfdq and dfdv (g × g per group,
  /// column-major like glm's Mat3: entry (r, c) of group b at b·g² + c·g + r). They must be the force() and the blocks that
  /// forceDifferential() applies, so that the direct solve and conjugate gradients solve one system.
  /// The default (never called for a coupled system) writes zeros.
  virtual void uncoupledForce(Real t, std::span<const Real> q, std::span<const Real> v, std::size_t first,
                              std::span<Real> f, std::span<Real> dfdq, std::span<Real> dfdv) const;
  /// Called by an integrator after it changed positions and velocities (e.g. to refresh caches).
  virtual void stateChanged() {}

  /// a = M⁻¹ f(t, q, v). The default is force() followed by a pass that scales by M⁻¹; a system that can
  /// compute (f_i)·M⁻¹_i in the same pass as its force overrides it (one pass instead of two over the
  /// coordinates: the in-place methods call it once or twice per step, the Runge–Kutta stages once each).
  virtual void acceleration(Real t, std::span<const Real> q, std::span<const Real> v, std::span<Real> out) const;

  // OdeSystem, in terms of the split: s = (q, v), ṡ = (v, M⁻¹ f).
  std::size_t stateSize() const final { return 2 * dofCount(); }
  void getState(std::span<Real> out) const final;
  void setState(std::span<const Real> state) final;
  void derivative(Real t, std::span<const Real> state, std::span<Real> out) const final;

 private:
  /// Scratch of the default forceDifferential (perturbed q, v and the second force), sized on first use:
  /// the finite difference allocates nothing per call.
  std::vector<Real> differenceScratch_;
};

/// A SecondOrderSystem that owns its state s = (q, v) as one array (the coordinates, then the
/// velocities) and its inverse masses as another: the storage and the views every small closed-form
/// system (oscillator, orbit, pendulum) needs; a subclass adds its force. It lends the state array to
/// the generic methods (stateStorage()), so that they advance it in place.
class OwnedStateSystem : public SecondOrderSystem {
 public:
  std::size_t dofCount() const override { return w_.size(); }
  std::span<Real> positions() override { return std::span<Real>(s_).first(w_.size()); }
  std::span<const Real> positions() const override { return std::span<const Real>(s_).first(w_.size()); }
  std::span<Real> velocities() override { return std::span<Real>(s_).subspan(w_.size()); }
  std::span<const Real> velocities() const override { return std::span<const Real>(s_).subspan(w_.size()); }
  std::span<const Real> inverseMasses() const override { return w_; }
  std::span<Real> stateStorage() override { return s_; }

 protected:
  /// q, v and w of equal length.
  OwnedStateSystem(const std::vector<Real>& q, const std::vector<Real>& v, std::vector<Real> w);
  std::vector<Real> w_;  ///< M⁻¹ per coordinate (0 = pinned)

 private:
  std::vector<Real> s_;  ///< (q, v): coordinates, then velocities (2 dofCount() values)
};

}  // namespace pba::ode
