#pragma once
// The Jacobian of the current pose as the IK lab shows it for the Jacobian methods (IK slides,
// "Columns"; Buss 2004 §3–5): a heat map of J (rows: x, y, z of each effector, then the scaled
// orientation rows of 6-DOF effectors; columns: the DOFs, grouped by joint) and its singular values,
// with the method's damping λ (DLS) or cut-off (pseudo-inverse) drawn against them.
#include <string>
#include <vector>

#include "app/runner/scene.h"
#include "physics/ik/jacobian.h"
#include "physics/ik/solver.h"

namespace pba::lab {

struct JacobianView {
  pba::ik::Matrix J;
  std::vector<Real> sigma;             ///< singular values, decreasing
  std::vector<std::string> rowLabels;  ///< "x0", "y0", …, "rx0" (orientation rows)
  std::vector<int> jointOfColumn;      ///< joint index of each column (joint boundaries in the map)
};

/// J and its singular values at `pose` (the matrix the next Jacobian step would use).
JacobianView computeJacobianView(const pba::ik::Skeleton& s, const pba::ik::Pose& pose,
                                 const std::vector<pba::ik::Effector>& effectors, const pba::ik::SolveOptions& options);

/// True for the methods built on J: transpose, pseudo-inverse, DLS, SDLS.
bool usesJacobian(pba::ik::SolverKind kind);

/// The "Jacobian" window at the bottom of `column` (ImGui; window mode only).
void drawJacobianWindow(const JacobianView& view, const pba::ik::SolveOptions& options, const app::ScreenRect& column);

}  // namespace pba::lab
