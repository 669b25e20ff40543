#include "physics/coursework/ball_on_cloth.h"

#include <algorithm>
#include <limits>
#include "physics/cloth/forces.h"
#include "physics/cloth/xpbd.h"
#include "physics/exercises/not_implemented.h"

namespace pba::coursework {

BallContact ballParticleContact(const Vec3& particle, Real particleInverseMass, const Vec3& ball, Real ballInverseMass,
                                Real radius) {
  // BEGIN SOLUTION
  // C = |x_p − x_b| − r ≥ 0; ∇_p C = n̂, ∇_b C = −n̂ with n̂ = (x_p − x_b)/|x_p − x_b|.
  const Vec3 d = particle - ball;
  const Real distance = glm::length(d);
  const Real wSum = particleInverseMass + ballInverseMass;
  if (distance >= radius || distance < 1e-12 || wSum <= 0.0) return {};
  const Vec3 n = d / distance;
  const Real violation = distance - radius;  // < 0
  return {-(particleInverseMass / wSum) * violation * n, (ballInverseMass / wSum) * violation * n};
  // END SOLUTION
  // STUB: return exercises::notImplemented("CW2-1", BallContact{}, particle, particleInverseMass, ball, ballInverseMass, radius);
}

Result<BallOnCloth> buildBallOnCloth(const BallOnClothDesc& desc) {
  if (desc.resolution < 2) return Error{"resolution: must be at least 2"};
  if (!(desc.size > 0.0)) return Error{"size: must be positive"};
  if (!(desc.ballRadius > 0.0)) return Error{"ballRadius: must be positive"};
  if (!(desc.ballMass > 0.0)) return Error{"ballMass: must be positive"};
  if (!(desc.stretchCompliance >= 0.0)) return Error{"stretchCompliance: must be >= 0"};
  if (desc.iterations < 1) return Error{"iterations: must be at least 1"};
  if (!(desc.damping >= 0.0)) return Error{"damping: must be >= 0"};
  cloth::GridDesc grid;
  grid.resolutionX = grid.resolutionY = desc.resolution;
  grid.width = grid.height = desc.size;
  grid.center = Vec3(0.0, desc.clothHeight, 0.0);
  grid.pins = cloth::GridPins::None;
  grid.layout = cloth::SpringLayout::Mesh;
  cloth::ClothMaterial material;
  material.massPerArea = desc.massPerArea;
  material.stretchCompliance = material.shearCompliance = desc.stretchCompliance;
  auto built = cloth::buildClothGrid(grid, material);
  if (!built) return Error{built.error()};
  BallOnCloth scene;
  scene.cloth = std::move(built).value();
  const auto n = static_cast<std::uint32_t>(desc.resolution);
  for (const std::uint32_t corner : {0u, n - 1, n * (n - 1), n * n - 1})
    cloth::pin(scene.cloth, corner, scene.cloth.position[corner]);
  scene.ball = Ball{desc.ballStart, desc.ballVelocity, desc.ballRadius, 1.0 / desc.ballMass};
  scene.gravity = desc.gravity;
  scene.margin = desc.margin;
  scene.iterations = desc.iterations;
  scene.damping = desc.damping;
  return scene;
}

void stepBallOnCloth([[maybe_unused]] BallOnCloth& scene, [[maybe_unused]] Real h) {
  // BEGIN SOLUTION
  cloth::Cloth& c = scene.cloth;
  Ball& ball = scene.ball;
  const std::size_t n = c.size();
  scene.previous.assign(c.position.begin(), c.position.end());
  for (std::size_t i = 0; i < n; ++i) {
    if (c.inverseMass[i] <= 0.0) continue;
    c.velocity[i] += scene.gravity * h;
    c.position[i] += c.velocity[i] * h;
  }
  const Vec3 ballStart = ball.position;
  if (ball.inverseMass > 0.0) {
    ball.velocity += scene.gravity * h;
    ball.position += ball.velocity * h;
  }
  scene.lambda.assign(c.constraints.size(), 0.0);
  const auto compliance = cloth::constraintCompliance(c.material);
  const Real contactRadius = ball.radius + scene.margin;
  for (int it = 0; it < scene.iterations; ++it) {
    cloth::sweepDistanceConstraints(c.constraints, compliance, cloth::SweepMode{}, h, c.position, c.inverseMass,
                                    scene.lambda);
    for (std::size_t i = 0; i < n; ++i) {
      const BallContact k =
          ballParticleContact(c.position[i], c.inverseMass[i], ball.position, ball.inverseMass, contactRadius);
      c.position[i] += k.particle;
      ball.position += k.ball;
    }
  }
  const Real keep = std::max(0.0, 1.0 - scene.damping * h);
  for (std::size_t i = 0; i < n; ++i) c.velocity[i] = keep * (c.position[i] - scene.previous[i]) / h;
  ball.velocity = keep * (ball.position - ballStart) / h;
  scene.time += h;
  // END SOLUTION
  // STUB: exercises::markNotImplemented("CW2-2");  // the scene stays where it is
}

Vec3 totalMomentum(const BallOnCloth& scene) {
  Vec3 p(0.0);
  const cloth::Cloth& c = scene.cloth;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c.inverseMass[i] > 0.0) p += c.velocity[i] / c.inverseMass[i];
  if (scene.ball.inverseMass > 0.0) p += scene.ball.velocity / scene.ball.inverseMass;
  return p;
}

Real deepestBallPenetration(const BallOnCloth& scene) {
  Real smallest = std::numeric_limits<Real>::infinity();
  for (const Vec3& x : scene.cloth.position)
    smallest = std::min(smallest, glm::length(x - scene.ball.position) - scene.ball.radius - scene.margin);
  return smallest;
}

}  // namespace pba::coursework
