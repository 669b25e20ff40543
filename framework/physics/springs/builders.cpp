#include "physics/springs/builders.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "physics/core/validate.h"

namespace pba::springs {
namespace {
Status checkSpring(std::string_view prefix, Real stiffness, Real damping) {
  if (Status s = checkRange(std::string(prefix) + ".stiffness", stiffness, 0.0, 1e9); !s) return s;
  return checkRange(std::string(prefix) + ".damping", damping, 0.0, 1e6);
}
void addSpring(particles::ParticleSystem& sys, std::size_t i, std::size_t j, Real k, Real c) {
  const Real rest = glm::length(sys.particles.position[j] - sys.particles.position[i]);
  sys.springs.push_back(Spring{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), rest, k, c});
}
}  // namespace

Status validate(const RopeDesc& d) {
  if (d.segments < 1 || d.segments > 100000)
    return Error{"rope.segments: must be in [1, 100000], got " + std::to_string(d.segments)};
  if (Status s = checkPositive("rope.mass", d.mass); !s) return s;
  if (Status s = checkFinite("rope.start", d.start); !s) return s;
  if (Status s = checkFinite("rope.end", d.end); !s) return s;
  if (glm::length(d.end - d.start) <= 1e-9) return Error{"rope.end: must differ from rope.start"};
  return checkSpring("rope", d.stiffness, d.damping);
}

Result<std::size_t> appendRope(const RopeDesc& d, particles::ParticleSystem& sys) {
  if (Status s = validate(d); !s) return Error{s.error()};
  const std::size_t first = sys.particles.size();
  const int n = d.segments + 1;
  const Real m = d.mass / n;
  for (int k = 0; k < n; ++k) {
    const Real s = static_cast<Real>(k) / d.segments;
    const bool pinned = (k == 0 && d.pinStart) || (k == n - 1 && d.pinEnd);
    sys.particles.add(d.start + s * (d.end - d.start), Vec3(0.0), pinned ? 0.0 : m, colors::kOrange);
  }
  for (int k = 0; k + 1 < n; ++k) addSpring(sys, first + k, first + k + 1, d.stiffness, d.damping);
  if (d.bending) {
    for (int k = 0; k + 2 < n; ++k) addSpring(sys, first + k, first + k + 2, 0.5 * d.stiffness, d.damping);
  }
  sys.syncMasses();
  return first;
}

Status validate(const BlobDesc& d) {
  if (d.surfaceParticles < 8 || d.surfaceParticles > 100000)
    return Error{"blob.surfaceParticles: must be in [8, 100000]"};
  if (d.neighbours < 3 || d.neighbours >= d.surfaceParticles)
    return Error{"blob.neighbours: must be in [3, surfaceParticles)"};
  if (Status s = checkPositive("blob.radius", d.radius); !s) return s;
  if (Status s = checkPositive("blob.mass", d.mass); !s) return s;
  if (Status s = checkFinite("blob.center", d.center); !s) return s;
  return checkSpring("blob", d.stiffness, d.damping);
}

Result<std::size_t> appendBlob(const BlobDesc& d, particles::ParticleSystem& sys) {
  if (Status s = validate(d); !s) return Error{s.error()};
  const std::size_t first = sys.particles.size();
  const int n = d.surfaceParticles;
  const Real m = d.mass / (n + 1);
  const Real golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const Real y = 1.0 - 2.0 * (k + 0.5) / n;
    const Real r = std::sqrt(1.0 - y * y);
    const Real phi = golden * k;
    sys.particles.add(d.center + d.radius * Vec3(r * std::cos(phi), y, r * std::sin(phi)), Vec3(0.0), m,
                      colors::kPurple);
  }
  const std::size_t center = sys.particles.add(d.center, Vec3(0.0), m, colors::kPurple);
  std::vector<std::size_t> order(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const Vec3 pk = sys.particles.position[first + k];
    std::iota(order.begin(), order.end(), first);
    std::partial_sort(order.begin(), order.begin() + d.neighbours + 1, order.end(), [&](std::size_t a, std::size_t b) {
      return glm::length(sys.particles.position[a] - pk) < glm::length(sys.particles.position[b] - pk);
    });
    for (int q = 1; q <= d.neighbours; ++q) {  // order[0] is k itself
      const std::size_t j = order[static_cast<std::size_t>(q)];
      if (j > first + k) addSpring(sys, first + k, j, d.stiffness, d.damping);  // once per pair… mostly
    }
    addSpring(sys, first + k, center, d.stiffness, d.damping);
  }
  sys.syncMasses();
  return first;
}

Status validate(const LatticeDesc& d) {
  for (int c : {d.nx, d.ny, d.nz}) {
    if (c < 2 || c > 200) return Error{"lattice.nx/ny/nz: must be in [2, 200], got " + std::to_string(c)};
  }
  if (Status s = checkPositive("lattice.spacing", d.spacing); !s) return s;
  if (Status s = checkPositive("lattice.particleMass", d.particleMass); !s) return s;
  if (Status s = checkFinite("lattice.origin", d.origin); !s) return s;
  return checkSpring("lattice", d.stiffness, d.damping);
}

Result<std::size_t> appendLattice(const LatticeDesc& d, particles::ParticleSystem& sys) {
  if (Status s = validate(d); !s) return Error{s.error()};
  const std::size_t first = sys.particles.size();
  auto index = [&](int i, int j, int k) { return first + static_cast<std::size_t>((i * d.ny + j) * d.nz + k); };
  for (int i = 0; i < d.nx; ++i)
    for (int j = 0; j < d.ny; ++j)
      for (int k = 0; k < d.nz; ++k) {
        const bool pinned = d.pinTopLayer && j == d.ny - 1;
        sys.particles.add(d.origin + d.spacing * Vec3(i, j, k), Vec3(0.0), pinned ? 0.0 : d.particleMass,
                          colors::kGreen);
      }
  for (int i = 0; i < d.nx; ++i)
    for (int j = 0; j < d.ny; ++j)
      for (int k = 0; k < d.nz; ++k) {
        // Neighbours with a lexicographically positive offset: each pair once.
        for (int di = 0; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -1; dk <= 1; ++dk) {
              if (di == 0 && (dj < 0 || (dj == 0 && dk <= 0))) continue;
              const int ni = i + di, nj = j + dj, nk = k + dk;
              if (nj < 0 || nj >= d.ny || nk < 0 || nk >= d.nz || ni >= d.nx) continue;
              const int axes = di * di + dj * dj + dk * dk;
              if (axes > 1 && !d.shear) continue;
              addSpring(sys, index(i, j, k), index(ni, nj, nk), d.stiffness, d.damping);
            }
      }
  sys.syncMasses();
  return first;
}

}  // namespace pba::springs
