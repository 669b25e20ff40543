#pragma once
// Scene builders shared by the pba-rigid lab, the tests and the benchmarks (docs/architecture.md §1; Box2D's
// shared/ scenes). Each fills a World and returns the bodies a caller wants to watch. Sizes in metres,
// masses in kilograms; the ground is the plane y = 0 unless said otherwise.
#include <vector>

#include "physics/rigid/world.h"

namespace pba::rigid {

/// A static ground plane y = 0 with friction μ; returns its index.
int addGround(World& world, Real friction = 0.6);
/// A dynamic box; returns its index (the description must be valid: builders use checked values).
int addBox(World& world, const Vec3& halfExtents, const Vec3& position, const Quat& orientation, Real density,
           Real friction, const Color& color);

struct StackDesc {
  int columnHeight = 10;  ///< boxes in the vertical stack
  int pyramidBase = 20;   ///< boxes in the pyramid's bottom row (base 20: 210 boxes)
  Real halfExtent = 0.5;  ///< [m] cube half size
  Real friction = 0.6;
  Real gap = 0.01;  ///< [m] horizontal gap between neighbours in a pyramid row
};
struct StackBodies {
  int columnTop = -1, pyramidTop = -1;
  std::vector<int> boxes;
};
StackBodies buildStack(World& world, const StackDesc& desc);

/// A static ramp tilted by `angle` [rad] about z (downhill is −x along it) with a cube of half size
/// `halfExtent` at rest on it, both with friction μ (their combination √(μμ) is μ).
struct Incline {
  int ramp = -1, box = -1;
  Vec3 start{0.0};     ///< [m] the cube's centre at rest
  Vec3 downhill{0.0};  ///< unit, along the slope
  Quat rotation{1, 0, 0, 0};
};
Incline buildIncline(World& world, Real angle, Real friction, Real halfExtent = 0.25);

/// Bullet's "3000 boxes" benchmark (BenchmarkDemo test 1): 47 layers of 8 × 8 cubes of half extent 1 and
/// mass 2, 1 m apart, each layer shifted and spread a little, so the columns lean and fall.
std::vector<BodyDesc> benchBoxes(int layers = 47, int size = 8);
/// Bullet's "1000 stack" (BenchmarkDemo test 2): a 12-layer square pyramid (650), three triangular
/// walls of 12 (3 × 78) and a round tower of 8 rings of 24 (192): 1,076 unit cubes of mass 1.
std::vector<BodyDesc> benchStack1000();
/// Adds every description to the world (returns the indices).
std::vector<int> addAll(World& world, const std::vector<BodyDesc>& descs);

/// A free T-handle (the Dzhanibekov effect): a shaft along y with a bar along x at its top, spinning
/// about its intermediate principal axis with a small perturbation, without gravity. Its inertia is the
/// two boxes' (Mirtich, moved by the parallel-axis theorem); its collision shape is only a small sphere
/// (nothing is near). `parts` are the two boxes relative to the centre of mass, for drawing.
struct THandle {
  int body = -1;
  Vec3 barCenter{0.0}, barHalf{0.0}, shaftCenter{0.0}, shaftHalf{0.0};  ///< [m] body frame
  Vec3 principalMoments{0.0};                                           ///< [kg·m²] I_x, I_y, I_z
};
THandle buildTHandle(World& world, Real spin = 6.0, Real perturbation = 0.01);

/// Newton's cradle: `count` steel balls of radius r hanging `gap` [m] apart on rigid distance joints of
/// length L, the first one pulled back by `liftAngle` [rad]. Returns the balls. Sequential impulses
/// resolve the impacts one by one only if the gap exceeds the speculative distance and a ball's travel
/// in one step (the `cradle` scene: 4 mm, 1 mm and 3.4 mm at 480 Hz); touching balls share one
/// simultaneous impulse and the momentum spreads instead of passing along the row.
std::vector<int> buildCradle(World& world, int count, Real radius, Real length, Real restitution, Real liftAngle,
                             Real gap = 0.004);

/// A row of dominoes (thin boxes) on the ground, the first one tipped; returns them.
std::vector<int> buildDominoes(World& world, int count, Real spacing, Real friction);

/// A chain of `links` capsules joined by hinges (axis z) to each other and the first to the world at
/// `top`, or by ball joints when `ball`, laid out from `top` along the unit `direction` in the x–y
/// plane (default: horizontal, so it swings down). Returns the links.
std::vector<int> buildChain(World& world, const Vec3& top, int links, Real linkLength, bool ball, Real density = 500.0,
                            const Vec3& direction = Vec3(1.0, 0.0, 0.0));

/// `count` mixed bodies in a loose cloud above the ground (seeded): per eight, a sphere, a capsule, three
/// boxes and three convex hulls of 10 random points; returns them.
std::vector<int> buildPile(World& world, int count, unsigned seed);

}  // namespace pba::rigid
