#include "physics/rigid/builders.h"

#include <cmath>
#include <random>

namespace pba::rigid {

namespace {
const Color kPalette[] = {colors::kBlue, colors::kOrange, colors::kGreen, colors::kPurple,
                          colors::kTeal, colors::kYellow, colors::kPink,  colors::kRed};
Color paletteColor(std::size_t i) { return kPalette[i % (sizeof(kPalette) / sizeof(kPalette[0]))]; }

int add(World& world, const BodyDesc& d) {
  const Result<int> r = world.addBody(d);
  return r ? r.value() : -1;
}
}  // namespace

int addGround(World& world, Real friction) {
  BodyDesc g;
  g.type = BodyType::Static;
  g.shape = collision::makePlane();
  g.friction = friction;
  g.color = colors::kGrey;
  g.name = "ground";
  return add(world, g);
}

int addBox(World& world, const Vec3& h, const Vec3& position, const Quat& orientation, Real density, Real friction,
           const Color& color) {
  BodyDesc d;
  d.shape = collision::makeBox(h).value();
  d.position = position;
  d.orientation = orientation;
  d.density = density;
  d.friction = friction;
  d.color = color;
  return add(world, d);
}

StackBodies buildStack(World& world, const StackDesc& s) {
  StackBodies out;
  const Real h = s.halfExtent;
  const Quat identity(1, 0, 0, 0);
  // The column, left of the pyramid.
  const Real columnX = -(s.pyramidBase * (2.0 * h + s.gap)) * 0.5 - 4.0 * h;
  for (int i = 0; i < s.columnHeight; ++i) {
    out.columnTop =
        addBox(world, Vec3(h), Vec3(columnX, h + 2.0 * h * i, 0.0), identity, 1000.0, s.friction, paletteColor(i));
    out.boxes.push_back(out.columnTop);
  }
  // The pyramid: row k has base − k boxes, each resting on two below.
  const Real pitch = 2.0 * h + s.gap;
  for (int row = 0; row < s.pyramidBase; ++row) {
    const int n = s.pyramidBase - row;
    const Real x0 = -0.5 * (n - 1) * pitch;
    for (int i = 0; i < n; ++i) {
      out.pyramidTop = addBox(world, Vec3(h), Vec3(x0 + i * pitch, h + 2.0 * h * row, 0.0), identity, 1000.0,
                              s.friction, paletteColor(row + 3));
      out.boxes.push_back(out.pyramidTop);
    }
  }
  return out;
}

Incline buildIncline(World& world, Real angle, Real friction, Real halfExtent) {
  Incline out;
  out.rotation = glm::angleAxis(angle, Vec3(0.0, 0.0, 1.0));
  const Vec3 rampHalf(12.0, 0.25, 1.5);
  const Vec3 rampCenter(0.0, 4.0, 0.0);
  BodyDesc ramp;
  ramp.type = BodyType::Static;
  ramp.shape = collision::makeBox(rampHalf).value();
  ramp.position = rampCenter;
  ramp.orientation = out.rotation;
  ramp.friction = friction;
  ramp.color = colors::kGrey;
  out.ramp = add(world, ramp);
  const Vec3 normal = out.rotation * kUp;
  out.downhill = out.rotation * Vec3(-1.0, 0.0, 0.0);
  out.start = rampCenter + (rampHalf.y + halfExtent) * normal - 0.6 * rampHalf.x * out.downhill;
  BodyDesc box;
  box.shape = collision::makeBox(Vec3(halfExtent)).value();
  box.position = out.start;
  box.orientation = out.rotation;
  box.friction = friction;
  box.color = colors::kOrange;
  box.name = "slider";
  out.box = add(world, box);
  return out;
}

namespace {
BodyDesc unitBox(const Vec3& position, const Quat& orientation, Real halfExtent, Real mass, std::size_t colorIndex) {
  BodyDesc d;
  d.shape = collision::makeBox(Vec3(halfExtent)).value();
  d.position = position;
  d.orientation = orientation;
  d.mass = mass;
  d.friction = 0.5;  // Bullet's default friction
  d.color = paletteColor(colorIndex);
  return d;
}
}  // namespace

std::vector<BodyDesc> benchBoxes(int layers, int size) {
  // BenchmarkDemo::createTest1: cubeSize 1 (half extent), spacing 1, mass 2.
  std::vector<BodyDesc> out;
  const Real cube = 1.0;
  Real spacing = cube;
  Vec3 pos(0.0, cube * 2.0, 0.0);
  Real offset = -size * (cube * 2.0 + spacing) * 0.5;
  for (int k = 0; k < layers; ++k) {
    for (int j = 0; j < size; ++j) {
      pos.z = offset + j * (cube * 2.0 + spacing);
      for (int i = 0; i < size; ++i) {
        pos.x = offset + i * (cube * 2.0 + spacing);
        out.push_back(unitBox(pos, Quat(1, 0, 0, 0), cube, 2.0, static_cast<std::size_t>(k)));
      }
    }
    offset -= 0.05 * spacing * (size - 1);
    spacing *= 1.01;
    pos.y += cube * 2.0 + spacing;
  }
  return out;
}

std::vector<BodyDesc> benchStack1000() {
  std::vector<BodyDesc> out;
  const Real c = 1.0;
  const Real spacing = 0.0001;
  // Square pyramid of 12 layers at x = −20 (BenchmarkDemo::createPyramid).
  {
    const int n = 12;
    Real offsetX = -n * (c * 2.0 + spacing) * 0.5, offsetZ = offsetX;
    Real y = c;
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < n - k; ++j)
        for (int i = 0; i < n - k; ++i)
          out.push_back(unitBox(Vec3(-20.0 + offsetX + i * (2.0 * c + spacing), y, offsetZ + j * (2.0 * c + spacing)),
                                Quat(1, 0, 0, 0), c, 1.0, static_cast<std::size_t>(k)));
      offsetX += c, offsetZ += c;
      y += 2.0 * c + spacing;
    }
  }
  // Three triangular walls of 12 in the y–z plane at x = −2, 4, 10 (BenchmarkDemo::createWall).
  for (Real x : {-2.0, 4.0, 10.0}) {
    const int n = 12;
    Real y = c;
    Real z0 = -n * c;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n - i; ++j)
        out.push_back(
            unitBox(Vec3(x, y, z0 + c * i + j * 2.0 * c), Quat(1, 0, 0, 0), c, 1.0, static_cast<std::size_t>(i + 2)));
      y += 2.0 * c;
    }
  }
  // A round tower of 8 rings of 24 at x = 25 (BenchmarkDemo::createTowerCircle).
  {
    const int rings = 8, perRing = 24;
    const Real radius = 1.3 * perRing * c / kPi;
    const Real step = 2.0 * kPi / perRing;
    Real angle = 0.0;
    Real y = c;
    for (int k = 0; k < rings; ++k) {
      for (int i = 0; i < perRing; ++i) {
        const Real a = angle + i * step;
        const Quat q = glm::angleAxis(a, kUp);
        out.push_back(unitBox(Vec3(25.0 + radius * std::sin(a), y, radius * std::cos(a)), q, c, 1.0,
                              static_cast<std::size_t>(k)));
      }
      angle += 0.5 * step;
      y += 2.0 * c;
    }
  }
  return out;
}

std::vector<int> addAll(World& world, const std::vector<BodyDesc>& descs) {
  std::vector<int> out;
  out.reserve(descs.size());
  for (const BodyDesc& d : descs) out.push_back(add(world, d));
  return out;
}

THandle buildTHandle(World& world, Real spin, Real perturbation) {
  THandle t;
  const Real density = 2700.0;  // aluminium
  t.barHalf = Vec3(0.4, 0.05, 0.05);
  t.shaftHalf = Vec3(0.05, 0.3, 0.05);
  const Vec3 barAt(0.0, 0.35, 0.0), shaftAt(0.0, 0.0, 0.0);
  const collision::MassProperties bar = collision::polyhedronMass(collision::boxHull(t.barHalf), density);
  const collision::MassProperties shaft = collision::polyhedronMass(collision::boxHull(t.shaftHalf), density);
  const Real mass = bar.mass + shaft.mass;
  const Vec3 com = (bar.mass * barAt + shaft.mass * shaftAt) / mass;
  // Parallel-axis theorem: I = I_c + m (|d|² 1 − d dᵀ) for a part whose centre is d from the body's.
  auto moved = [](const collision::MassProperties& m, const Vec3& d) {
    Mat3 shift(glm::dot(d, d));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) shift[c][r] -= d[r] * d[c];
    return m.inertia + m.mass * shift;
  };
  const Mat3 inertia = moved(bar, barAt - com) + moved(shaft, shaftAt - com);
  t.barCenter = barAt - com;
  t.shaftCenter = shaftAt - com;
  t.principalMoments = Vec3(inertia[0][0], inertia[1][1], inertia[2][2]);
  BodyDesc d;
  d.shape = collision::makeSphere(0.05).value();
  d.position = Vec3(0.0, 1.5, 0.0);
  d.mass = mass;
  d.inertia = inertia;
  d.gravityScale = 0.0;
  d.allowSleep = false;
  d.color = colors::kOrange;
  d.name = "t-handle";
  // I_y (about the shaft) is the smallest, I_z the largest: x, along the bar, is the intermediate axis.
  d.angularVelocity = Vec3(spin, perturbation, perturbation);
  t.body = add(world, d);
  return t;
}

std::vector<int> buildCradle(World& world, int count, Real r, Real length, Real restitution, Real liftAngle, Real gap) {
  std::vector<int> balls;
  const Real top = length + r + 0.5;
  for (int i = 0; i < count; ++i) {
    const Real x = (i - 0.5 * (count - 1)) * (2.0 * r + gap);
    Vec3 anchor(x, top, 0.0);
    Vec3 p = anchor - Vec3(0.0, length, 0.0);
    if (i == 0) p = anchor + length * Vec3(-std::sin(liftAngle), -std::cos(liftAngle), 0.0);
    BodyDesc d;
    d.shape = collision::makeSphere(r).value();
    d.position = p;
    d.density = 7850.0;
    d.restitution = restitution;
    d.friction = 0.0;
    d.allowSleep = false;
    d.color = colors::kGrey;
    d.name = "ball " + std::to_string(i);
    const int b = add(world, d);
    balls.push_back(b);
    JointDesc j;
    j.kind = JointKind::Distance;
    j.bodyA = -1;
    j.bodyB = b;
    j.anchor = anchor;
    j.anchorB = p;
    world.addJoint(j);
  }
  return balls;
}

std::vector<int> buildDominoes(World& world, int count, Real spacing, Real friction) {
  std::vector<int> out;
  const Vec3 h(0.05, 0.5, 0.25);
  for (int i = 0; i < count; ++i) {
    Quat q(1, 0, 0, 0);
    Vec3 p(i * spacing - 0.5 * count * spacing, h.y, 0.0);
    if (i == 0) {
      q = glm::angleAxis(-0.25, Vec3(0, 0, 1));
      p.y = h.y * std::cos(0.25) + h.x * std::sin(0.25) + 0.01;
    }
    out.push_back(addBox(world, h, p, q, 600.0, friction, paletteColor(i)));
  }
  return out;
}

std::vector<int> buildChain(World& world, const Vec3& top, int links, Real linkLength, bool ball, Real density,
                            const Vec3& direction) {
  std::vector<int> out;
  const Real r = 0.1 * linkLength;
  int previous = -1;
  for (int i = 0; i < links; ++i) {
    BodyDesc d;
    d.shape = collision::makeCapsule(0.5 * linkLength - r, r).value();
    d.position = top + (i + 0.5) * linkLength * direction;
    // Capsule axis (local y) along the direction: a rotation about z.
    d.orientation = glm::angleAxis(std::atan2(-direction.x, direction.y), Vec3(0, 0, 1));
    d.density = density;
    d.color = paletteColor(i);
    const int b = add(world, d);
    JointDesc j;
    j.kind = ball ? JointKind::Ball : JointKind::Hinge;
    j.bodyA = previous;
    j.bodyB = b;
    j.anchor = top + i * linkLength * direction;
    j.axis = Vec3(0.0, 0.0, 1.0);
    world.addJoint(j);
    out.push_back(b);
    previous = b;
  }
  return out;
}

std::vector<int> buildPile(World& world, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::normal_distribution<Real> n(0.0, 1.0);
  std::vector<int> out;
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<Real>(count))));
  const Real pitch = 0.7;
  for (int i = 0; i < count; ++i) {
    const int ix = i % side, iz = (i / side) % side, iy = i / (side * side);
    BodyDesc d;
    d.position =
        Vec3((ix - 0.5 * side) * pitch + 0.05 * u(rng), 0.6 + iy * pitch, (iz - 0.5 * side) * pitch + 0.05 * u(rng));
    d.orientation = glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
    d.density = 800.0;
    d.color = paletteColor(static_cast<std::size_t>(i + i / 8));  // every kind in every colour
    // One in eight a sphere, one a capsule, three boxes, three hulls (round shapes are the costly ones to
    // draw under software rendering).
    switch (i % 8) {
      case 0:
        d.shape = collision::makeSphere(0.15 + 0.08 * std::abs(u(rng))).value();
        break;
      case 1:
        d.shape = collision::makeCapsule(0.12 + 0.05 * std::abs(u(rng)), 0.1).value();
        break;
      case 2:
      case 3:
      case 4:
        d.shape =
            collision::makeBox(Vec3(0.12 + 0.08 * std::abs(u(rng)), 0.12 + 0.05 * std::abs(u(rng)), 0.15)).value();
        break;
      default: {
        std::vector<Vec3> pts;
        for (int k = 0; k < 10; ++k) pts.push_back(0.22 * glm::normalize(Vec3(n(rng), n(rng), n(rng))));
        Result<collision::Shape> hull = collision::makeHull(pts);
        d.shape = hull ? hull.value() : collision::makeSphere(0.2).value();
      }
    }
    out.push_back(add(world, d));
  }
  return out;
}

}  // namespace pba::rigid
