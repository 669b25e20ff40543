#include "physics/collision/mass.h"

#include <cmath>

namespace pba::collision {

MassProperties sphereMass(Real radius, Real density) {
  MassProperties m;
  m.mass = density * (4.0 / 3.0) * kPi * radius * radius * radius;
  m.inertia = Mat3(0.4 * m.mass * radius * radius);
  return m;
}

MassProperties cylinderMass(Real halfHeight, Real radius, Real density) {
  MassProperties m;
  const Real h = 2.0 * halfHeight;
  m.mass = density * kPi * radius * radius * h;
  const Real perpendicular = m.mass * (radius * radius / 4.0 + h * h / 12.0);
  m.inertia = Mat3(0.0);
  m.inertia[0][0] = m.inertia[2][2] = perpendicular;
  m.inertia[1][1] = 0.5 * m.mass * radius * radius;
  return m;
}

MassProperties capsuleMass(Real halfHeight, Real radius, Real density) {
  const MassProperties cylinder = cylinderMass(halfHeight, radius, density);
  const Real r2 = radius * radius;
  const Real h = 2.0 * halfHeight;
  const Real caps = density * (4.0 / 3.0) * kPi * r2 * radius;  // both hemispheres together [kg]
  // Caps about the capsule's axis: (2/5) m r². Perpendicular: each cap has (83/320) m r² about its own
  // centre of mass, which lies h/2 + 3r/8 from the centre: together caps·(2r²/5 + h²/4 + 3hr/8).
  MassProperties m = cylinder;
  m.mass += caps;
  m.inertia[1][1] += 0.4 * caps * r2;
  const Real perpendicular = caps * (0.4 * r2 + h * h / 4.0 + 3.0 * h * radius / 8.0);
  m.inertia[0][0] += perpendicular;
  m.inertia[2][2] += perpendicular;
  return m;
}

namespace {

// Mirtich §4, "compProjectionIntegrals": line integrals over the boundary of a face projected onto the
// coordinate plane (α, β) = (A, B), accumulated edge by edge (Green's theorem).
struct ProjectionIntegrals {
  Real P1 = 0, Pa = 0, Pb = 0, Paa = 0, Pab = 0, Pbb = 0, Paaa = 0, Paab = 0, Pabb = 0, Pbbb = 0;
};

ProjectionIntegrals projectionIntegrals(const ConvexHull& hull, const HullFace& face, int A, int B) {
  ProjectionIntegrals p;
  const std::size_t n = face.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& v0 = hull.vertices[face.vertices[i]];
    const Vec3& v1 = hull.vertices[face.vertices[(i + 1) % n]];
    const Real a0 = v0[A], b0 = v0[B], a1 = v1[A], b1 = v1[B];
    const Real da = a1 - a0, db = b1 - b0;
    const Real a0_2 = a0 * a0, a0_3 = a0_2 * a0, a0_4 = a0_3 * a0;
    const Real b0_2 = b0 * b0, b0_3 = b0_2 * b0, b0_4 = b0_3 * b0;
    const Real a1_2 = a1 * a1, a1_3 = a1_2 * a1;
    const Real b1_2 = b1 * b1, b1_3 = b1_2 * b1;
    const Real C1 = a1 + a0;
    const Real Ca = a1 * C1 + a0_2, Caa = a1 * Ca + a0_3, Caaa = a1 * Caa + a0_4;
    const Real Cb = b1 * (b1 + b0) + b0_2, Cbb = b1 * Cb + b0_3, Cbbb = b1 * Cbb + b0_4;
    const Real Cab = 3 * a1_2 + 2 * a1 * a0 + a0_2, Kab = a1_2 + 2 * a1 * a0 + 3 * a0_2;
    const Real Caab = a0 * Cab + 4 * a1_3, Kaab = a1 * Kab + 4 * a0_3;
    const Real Cabb = 4 * b1_3 + 3 * b1_2 * b0 + 2 * b1 * b0_2 + b0_3;
    const Real Kabb = b1_3 + 2 * b1_2 * b0 + 3 * b1 * b0_2 + 4 * b0_3;
    p.P1 += db * C1;
    p.Pa += db * Ca;
    p.Paa += db * Caa;
    p.Paaa += db * Caaa;
    p.Pb += da * Cb;
    p.Pbb += da * Cbb;
    p.Pbbb += da * Cbbb;
    p.Pab += db * (b1 * Cab + b0 * Kab);
    p.Paab += db * (b1 * Caab + b0 * Kaab);
    p.Pabb += da * (a1 * Cabb + a0 * Kabb);
  }
  p.P1 /= 2.0;
  p.Pa /= 6.0;
  p.Paa /= 12.0;
  p.Paaa /= 20.0;
  p.Pb /= -6.0;
  p.Pbb /= -12.0;
  p.Pbbb /= -20.0;
  p.Pab /= 24.0;
  p.Paab /= 60.0;
  p.Pabb /= -60.0;
  return p;
}

// Mirtich §4, "compFaceIntegrals": surface integrals over the face from the projected ones, using the
// face plane n·x + w = 0 to express γ = C through α and β.
struct FaceIntegrals {
  Real Fa, Fb, Fc, Faa, Fbb, Fcc, Faaa, Fbbb, Fccc, Faab, Fbbc, Fcca;
};

FaceIntegrals faceIntegrals(const ConvexHull& hull, const HullFace& face, int A, int B, int C) {
  const ProjectionIntegrals p = projectionIntegrals(hull, face, A, B);
  const Vec3& n = face.normal;
  const Real w = -face.offset;
  const Real k1 = 1.0 / n[C], k2 = k1 * k1, k3 = k2 * k1, k4 = k3 * k1;
  const Real nA = n[A], nB = n[B];
  FaceIntegrals f{};
  f.Fa = k1 * p.Pa;
  f.Fb = k1 * p.Pb;
  f.Fc = -k2 * (nA * p.Pa + nB * p.Pb + w * p.P1);
  f.Faa = k1 * p.Paa;
  f.Fbb = k1 * p.Pbb;
  f.Fcc = k3 * (nA * nA * p.Paa + 2 * nA * nB * p.Pab + nB * nB * p.Pbb + w * (2 * (nA * p.Pa + nB * p.Pb) + w * p.P1));
  f.Faaa = k1 * p.Paaa;
  f.Fbbb = k1 * p.Pbbb;
  f.Fccc = -k4 * (nA * nA * nA * p.Paaa + 3 * nA * nA * nB * p.Paab + 3 * nA * nB * nB * p.Pabb +
                  nB * nB * nB * p.Pbbb + 3 * w * (nA * nA * p.Paa + 2 * nA * nB * p.Pab + nB * nB * p.Pbb) +
                  w * w * (3 * (nA * p.Pa + nB * p.Pb) + w * p.P1));
  f.Faab = k1 * p.Paab;
  f.Fbbc = -k2 * (nA * p.Pabb + nB * p.Pbbb + w * p.Pbb);
  f.Fcca = k3 * (nA * nA * p.Paaa + 2 * nA * nB * p.Paab + nB * nB * p.Pabb +
                 w * (2 * (nA * p.Paa + nB * p.Pab) + w * p.Pa));
  return f;
}

}  // namespace

MassProperties polyhedronMass(const ConvexHull& hull, Real density) {
  // Mirtich §3, "compVolumeIntegrals": T0 = ∫dV, T1 = ∫(x, y, z) dV, T2 = ∫(x², y², z²) dV,
  // TP = ∫(xy, yz, zx) dV, each a sum over faces of n_k times a face integral (divergence theorem).
  Real T0 = 0.0;
  Vec3 T1(0.0), T2(0.0), TP(0.0);
  for (const HullFace& face : hull.faces) {
    const Vec3& n = face.normal;
    const Vec3 a = glm::abs(n);
    const int C = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);  // project away the largest component
    const int A = (C + 1) % 3, B = (A + 1) % 3;
    const FaceIntegrals f = faceIntegrals(hull, face, A, B, C);
    T0 += n[0] * (A == 0 ? f.Fa : (B == 0 ? f.Fb : f.Fc));
    T1[A] += n[A] * f.Faa;
    T1[B] += n[B] * f.Fbb;
    T1[C] += n[C] * f.Fcc;
    T2[A] += n[A] * f.Faaa;
    T2[B] += n[B] * f.Fbbb;
    T2[C] += n[C] * f.Fccc;
    TP[A] += n[A] * f.Faab;
    TP[B] += n[B] * f.Fbbc;
    TP[C] += n[C] * f.Fcca;
  }
  T1 /= 2.0;
  T2 /= 3.0;
  TP /= 2.0;
  MassProperties m;
  m.mass = density * T0;
  m.centerOfMass = T1 / T0;
  // Inertia about the origin, then moved to the centre of mass (parallel-axis theorem).
  Mat3 J(0.0);
  J[0][0] = density * (T2.y + T2.z);
  J[1][1] = density * (T2.z + T2.x);
  J[2][2] = density * (T2.x + T2.y);
  J[0][1] = J[1][0] = -density * TP.x;
  J[1][2] = J[2][1] = -density * TP.y;
  J[2][0] = J[0][2] = -density * TP.z;
  const Vec3& r = m.centerOfMass;
  J[0][0] -= m.mass * (r.y * r.y + r.z * r.z);
  J[1][1] -= m.mass * (r.z * r.z + r.x * r.x);
  J[2][2] -= m.mass * (r.x * r.x + r.y * r.y);
  J[0][1] = J[1][0] = J[0][1] + m.mass * r.x * r.y;
  J[1][2] = J[2][1] = J[1][2] + m.mass * r.y * r.z;
  J[2][0] = J[0][2] = J[2][0] + m.mass * r.z * r.x;
  m.inertia = J;
  return m;
}

MassProperties shapeMass(const Shape& shape, Real density) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
      return sphereMass(shape.radius, density);
    case ShapeKind::Capsule:
      return capsuleMass(shape.halfHeight, shape.radius, density);
    case ShapeKind::Box:
    case ShapeKind::Hull:
      return polyhedronMass(*shape.hull, density);
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
      break;
  }
  return {};
}

}  // namespace pba::collision
