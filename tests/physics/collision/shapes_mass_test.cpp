// Shapes, hulls and mass properties. References: Mirtich's polyhedral integrals against an independent
// quadrature (a fan of tetrahedra, each integrated with the 4-point rule that is exact for quadratics);
// the capsule against a slice-by-slice integral of disks.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "physics/collision/mass.h"
#include "physics/collision/shapes.h"
#include "support/expect_helpers.h"

namespace pba::collision {
namespace {

/// ∫ρ dV, ∫ρ x dV and ∫ρ x xᵀ dV over a convex hull by tetrahedra from the vertex average, each with the
/// 4-point rule (barycentric (α, β, β, β), exact for polynomials of degree 2).
struct Moments {
  Real mass = 0.0;
  Vec3 first{0.0};
  Mat3 second{0.0};
};
Moments quadratureMoments(const ConvexHull& hull, Real density) {
  Vec3 apex(0.0);
  for (const Vec3& v : hull.vertices) apex += v;
  apex /= static_cast<Real>(hull.vertices.size());
  const Real alpha = 0.5854101966249685, beta = 0.1381966011250105;
  Moments m;
  for (const HullFace& f : hull.faces) {
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
      const Vec3 p[4] = {apex, hull.vertices[f.vertices[0]], hull.vertices[f.vertices[k]],
                         hull.vertices[f.vertices[k + 1]]};
      const Real volume = std::abs(glm::dot(p[1] - p[0], glm::cross(p[2] - p[0], p[3] - p[0]))) / 6.0;
      for (int q = 0; q < 4; ++q) {
        Vec3 x(0.0);
        for (int i = 0; i < 4; ++i) x += (i == q ? alpha : beta) * p[i];
        const Real w = density * volume / 4.0;
        m.mass += w;
        m.first += w * x;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) m.second[c][r] += w * x[r] * x[c];
      }
    }
  }
  return m;
}

/// Inertia about the centre of mass from the moments: I = tr(S) 1 − S with S = ∫ρ (x − c)(x − c)ᵀ.
Mat3 inertiaFromMoments(const Moments& m) {
  const Vec3 c = m.first / m.mass;
  Mat3 s = m.second;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) s[k][r] -= m.mass * c[r] * c[k];
  const Real trace = s[0][0] + s[1][1] + s[2][2];
  return Mat3(trace) - s;
}

void expectMatNear(const Mat3& a, const Mat3& b, Real tolerance) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "entry (" << r << ", " << c << ")";
}

TEST(ConvexHull, OfACubesCornersHasSixQuadFacesAndTwelveEdges) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  corners.emplace_back(0.2, 0.1, -0.3);  // interior points are dropped
  corners.emplace_back(1.0, 0.0, 0.0);   // a point on a face too
  const Result<ConvexHull> hull = buildConvexHull(corners);
  ASSERT_TRUE(hull.ok()) << hull.error();
  EXPECT_EQ(hull.value().vertices.size(), 8u);
  EXPECT_EQ(hull.value().faces.size(), 6u);
  EXPECT_EQ(hull.value().edges.size(), 12u);
  for (const HullFace& f : hull.value().faces) EXPECT_EQ(f.vertices.size(), 4u);
}

TEST(ConvexHull, OfRandomPointsContainsEveryPointAndSatisfiesEuler) {
  std::mt19937_64 rng(11);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 40; ++i) pts.emplace_back(n(rng), 0.5 * n(rng), 2.0 * n(rng));
    const Result<ConvexHull> hull = buildConvexHull(pts);
    ASSERT_TRUE(hull.ok()) << hull.error();
    const ConvexHull& h = hull.value();
    // Euler: V − E + F = 2 for a convex polyhedron.
    EXPECT_EQ(static_cast<int>(h.vertices.size()) - static_cast<int>(h.edges.size()) + static_cast<int>(h.faces.size()),
              2)
        << "seed 11, trial " << trial;
    for (const Vec3& p : pts)
      for (const HullFace& f : h.faces) EXPECT_LE(glm::dot(f.normal, p) - f.offset, 1e-9) << "trial " << trial;
  }
}

TEST(ConvexHull, RejectsCoplanarTooFewAndNonFinitePoints) {
  EXPECT_NE(buildConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "pile.hull").error().find("pile.hull: needs at least 4"),
            std::string::npos);
  EXPECT_NE(buildConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}).error().find("coplanar"), std::string::npos);
  EXPECT_NE(buildConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}}).error().find("points[3]: must be finite"),
            std::string::npos);
}

TEST(ShapeConstructors, RejectZeroNegativeAndNonFiniteSizesNamingTheField) {
  EXPECT_EQ(makeSphere(0.0, "ball").error(), "ball.radius: must be a finite number > 0, got 0");
  EXPECT_FALSE(makeCapsule(-1.0, 0.1).ok());
  EXPECT_NE(makeBox(Vec3(1.0, 0.0, 1.0), "crate").error().find("crate.halfExtents.y"), std::string::npos);
  EXPECT_FALSE(makeBox(Vec3(1.0, INFINITY, 1.0)).ok());
  EXPECT_TRUE(makeBox(Vec3(1.0, 2.0, 3.0)).ok());
}

TEST(MirtichMassProperties, MatchTetrahedralQuadratureForRandomHulls) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 25; ++i) pts.emplace_back(u(rng) + 0.3, 0.6 * u(rng) - 0.2, 1.4 * u(rng) + 0.1);
    const ConvexHull hull = buildConvexHull(pts).value();
    const Real density = 750.0;
    const MassProperties m = polyhedronMass(hull, density);
    const Moments q = quadratureMoments(hull, density);
    // Both are exact; the tolerance covers rounding over a few hundred terms.
    EXPECT_NEAR(m.mass, q.mass, 1e-11 * q.mass) << "seed 5, trial " << trial;
    EXPECT_VEC3_NEAR(m.centerOfMass, q.first / q.mass, 1e-12);
    expectMatNear(m.inertia, inertiaFromMoments(q), 1e-10 * q.mass);
  }
}

TEST(MirtichMassProperties, OfABoxMatchQuadratureAndAreDiagonal) {
  const ConvexHull hull = boxHull(Vec3(0.5, 1.0, 2.0));
  const MassProperties m = polyhedronMass(hull, 2.0);
  EXPECT_NEAR(m.mass, 2.0 * 8.0, 1e-12);  // volume 1 × 2 × 4
  expectMatNear(m.inertia, inertiaFromMoments(quadratureMoments(hull, 2.0)), 1e-11);
  EXPECT_NEAR(m.inertia[0][1], 0.0, 1e-12);
}

TEST(CapsuleMass, MatchesASliceBySliceIntegralOfDisks) {
  const Real hh = 0.7, r = 0.3, density = 1000.0;
  const MassProperties m = capsuleMass(hh, r, density);
  // A disk of radius ρ and mass dm at height y: I_y = dm ρ²/2, I_x = dm (ρ²/4 + y²). Simpson's rule
  // over y ∈ [−hh − r, hh + r] with ρ(y) the capsule's profile.
  const int n = 200000;
  const Real y0 = -hh - r, y1 = hh + r, dy = (y1 - y0) / n;
  Real mass = 0.0, iy = 0.0, ix = 0.0;
  for (int i = 0; i <= n; ++i) {
    const Real y = y0 + i * dy;
    const Real overhang = std::max(0.0, std::abs(y) - hh);
    const Real rho2 = std::max(0.0, r * r - overhang * overhang);
    const Real w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const Real dm = density * kPi * rho2;
    mass += w * dm;
    iy += w * dm * rho2 / 2.0;
    ix += w * dm * (rho2 / 4.0 + y * y);
  }
  mass *= dy / 3.0, iy *= dy / 3.0, ix *= dy / 3.0;
  EXPECT_NEAR(m.mass, mass, 1e-8 * mass);
  EXPECT_NEAR(m.inertia[1][1], iy, 1e-8 * iy);
  EXPECT_NEAR(m.inertia[0][0], ix, 1e-8 * ix);
  EXPECT_NEAR(m.inertia[2][2], ix, 1e-8 * ix);
}

TEST(ShapeAabb, ContainsEverySupportPointOfARotatedShape) {
  std::mt19937_64 rng(3);
  std::normal_distribution<Real> n(0.0, 1.0);
  const Shape shapes[] = {makeSphere(0.4).value(), makeCapsule(0.5, 0.2).value(), makeBox(Vec3(0.3, 0.6, 0.9)).value()};
  for (const Shape& s : shapes) {
    for (int trial = 0; trial < 50; ++trial) {
      const Transform pose{Vec3(n(rng), n(rng), n(rng)), glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)))};
      const Aabb box = computeAabb(s, pose);
      for (int k = 0; k < 20; ++k) {
        const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
        const Vec3 p = pose.apply(coreSupport(s, pose.rotateInverse(d))) + s.radius * d;
        for (int c = 0; c < 3; ++c) {
          EXPECT_LE(box.min[c], p[c] + 1e-12);
          EXPECT_GE(box.max[c], p[c] - 1e-12);
        }
      }
    }
  }
}

}  // namespace
}  // namespace pba::collision
