#pragma once
// Mass properties of shapes of uniform density: mass, centre of mass and the inertia tensor about the
// centre of mass in the shape's local frame.
#include "physics/collision/shapes.h"

namespace pba::collision {

struct MassProperties {
  Real mass = 0.0;         ///< [kg]
  Vec3 centerOfMass{0.0};  ///< [m] local frame
  Mat3 inertia{0.0};       ///< [kg·m²] about the centre of mass, local axes; symmetric
};

/// Solid sphere: I = (2/5) m r² on every axis.
MassProperties sphereMass(Real radius, Real density);
/// Solid cylinder with axis along local y, half height hh: I_y = m r²/2, I_x = I_z = m (r²/4 + (2hh)²/12).
MassProperties cylinderMass(Real halfHeight, Real radius, Real density);
/// Capsule along local y: a cylinder of height 2hh plus two hemispherical caps moved by the parallel-axis
/// theorem (each cap's centre of mass lies 3r/8 from its flat face).
MassProperties capsuleMass(Real halfHeight, Real radius, Real density);
/// Any closed polyhedron (faces counter-clockwise from outside) by Mirtich's algorithm: volume integrals
/// reduced to face integrals by the divergence theorem and to projected-polygon line integrals by
/// Green's theorem (B. Mirtich, "Fast and Accurate Computation of Polyhedral Mass Properties",
/// Journal of Graphics Tools 1(2), 1996, §3–4). Exact up to rounding. Boxes use this too.
MassProperties polyhedronMass(const ConvexHull& hull, Real density);
/// Dispatch on the shape kind; planes and meshes (static only) have no mass.
MassProperties shapeMass(const Shape& shape, Real density);

}  // namespace pba::collision
