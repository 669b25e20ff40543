#include "physics/cloth/pcg.h"

#include <algorithm>
#include <cmath>

namespace pba::cloth {
namespace {

Real sumDot(std::span<const Vec3> a, std::span<const Vec3> b) {
  Real s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += glm::dot(a[i], b[i]);
  return s;
}

Vec3 precondition(std::span<const Mat3> inverse, std::size_t i, const Vec3& r) {
  return inverse.empty() ? r : inverse[i] * r;
}

/// S y, inlined here with free particles (most of them) first.
inline Vec3 filtered(const ParticleFilter& f, const Vec3& y) {
  return f.kind == ParticleFilter::Kind::Free ? y : applyFilter(f, y);
}

/// v ← S v, particle by particle.
void filterInPlace(std::span<const ParticleFilter> filter, std::span<Vec3> v) {
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = filtered(filter[k], v[k]);
}

/// out ← P⁻¹ r.
void preconditionAll(std::span<const Mat3> inverse, std::span<const Vec3> r, std::span<Vec3> out) {
  for (std::size_t k = 0; k < r.size(); ++k) out[k] = precondition(inverse, k, r[k]);
}

}  // namespace

Vec3 applyFilter(const ParticleFilter& f, const Vec3& y) {
  switch (f.kind) {
    case ParticleFilter::Kind::Free:
      return y;
    case ParticleFilter::Kind::OneDirection:
      return y - glm::dot(f.p, y) * f.p;
    case ParticleFilter::Kind::TwoDirections:
      return y - glm::dot(f.p, y) * f.p - glm::dot(f.q, y) * f.q;
    case ParticleFilter::Kind::Fixed:
      return Vec3(0.0);
  }
  return y;
}

PcgStats filteredPcg(const ParticleOperator& A, std::span<const Vec3> b, std::span<const ParticleFilter> filter,
                     std::span<const Vec3> z, std::span<const Mat3> preconditionerInverse, const PcgSettings& settings,
                     std::span<Vec3> x, PcgWorkspace& w) {
  const std::size_t n = b.size();
  w.r.resize(n);
  w.c.resize(n);
  w.q.resize(n);
  w.s.resize(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = applyFilter(filter[i], x[i]) + (z[i] - applyFilter(filter[i], z[i]));

  // δ₀ from the filtered right-hand side; r = S (b − A x).
  Real delta0 = 0.0, bNorm2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 sb = applyFilter(filter[i], b[i]);
    delta0 += glm::dot(sb, precondition(preconditionerInverse, i, sb));
    bNorm2 += glm::dot(sb, sb);
  }
  A(x, w.q);
  std::transform(b.begin(), b.end(), w.q.begin(), w.r.begin(), [](const Vec3& bi, const Vec3& qi) { return bi - qi; });
  filterInPlace(filter, w.r);
  preconditionAll(preconditionerInverse, w.r, w.c);
  filterInPlace(filter, w.c);
  Real delta = sumDot(w.r, w.c);

  PcgStats stats;
  const Real eps2 = settings.tolerance * settings.tolerance;
  // Each pass over the particles does all the loop's work on them that no later sum waits for (q's filter
  // with cᵀq; x, r, s with rᵀs), in the order of the formulas, summing in index order as sumDot does.
  while (stats.iterations < settings.maxIterations && delta > eps2 * delta0) {
    A(w.c, w.q);
    Real cq = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      w.q[i] = filtered(filter[i], w.q[i]);
      cq += glm::dot(w.c[i], w.q[i]);
    }
    if (!(cq > 0.0)) break;  // not positive definite along c: keep the iterate (the caller reports it)
    const Real alpha = delta / cq;
    const Real deltaOld = delta;
    delta = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * w.c[i];
      w.r[i] -= alpha * w.q[i];
      w.s[i] = precondition(preconditionerInverse, i, w.r[i]);
      delta += glm::dot(w.r[i], w.s[i]);
    }
    const Real beta = delta / deltaOld;
    for (std::size_t i = 0; i < n; ++i) w.c[i] = filtered(filter[i], w.s[i] + beta * w.c[i]);
    ++stats.iterations;
  }
  stats.converged = delta <= eps2 * delta0;
  stats.relativeResidual = bNorm2 > 0.0 ? std::sqrt(sumDot(w.r, w.r) / bNorm2) : 0.0;
  return stats;
}

std::vector<std::uint32_t> colourParticles(std::size_t particles,
                                           std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs,
                                           std::uint32_t* count) {
  // Adjacency in compressed rows, then first-fit colouring in index order.
  std::vector<std::uint32_t> start(particles + 1, 0), neighbours(2 * pairs.size());
  for (const auto& [a, b] : pairs) {
    ++start[a + 1];
    ++start[b + 1];
  }
  for (std::size_t i = 0; i < particles; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& [a, b] : pairs) {
    neighbours[fill[a]++] = b;
    neighbours[fill[b]++] = a;
  }
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> colour(particles, kNone);
  std::vector<std::uint32_t> usedBy;  // usedBy[c] == i when a neighbour of i has colour c
  std::uint32_t colours = 0;
  for (std::uint32_t i = 0; i < particles; ++i) {
    for (std::uint32_t e = start[i]; e < start[i + 1]; ++e) {
      const std::uint32_t c = colour[neighbours[e]];
      if (c != kNone) usedBy[c] = i;
    }
    std::uint32_t c = 0;
    while (c < colours && usedBy[c] == i) ++c;
    if (c == colours) {
      ++colours;
      usedBy.push_back(kNone);
    }
    colour[i] = c;
  }
  if (count) *count = colours;
  return colour;
}

void probedBlockJacobi(const ParticleOperator& A, std::span<const std::uint32_t> colour, std::uint32_t colours,
                       std::vector<Mat3>& inverse, std::vector<Vec3>& in, std::vector<Vec3>& out) {
  const std::size_t n = colour.size();
  std::vector<Mat3>& blocks = inverse;  // filled with the blocks, then inverted in place
  blocks.assign(n, Mat3(0.0));
  in.assign(n, Vec3(0.0));
  out.resize(n);
  for (std::uint32_t c = 0; c < colours; ++c) {
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t i = 0; i < n; ++i) {
        in[i] = Vec3(0.0);
        if (colour[i] == c) in[i][axis] = 1.0;
      }
      A(in, out);
      for (std::size_t i = 0; i < n; ++i) {
        if (colour[i] == c) blocks[i][axis] = out[i];  // glm: column `axis`
      }
    }
  }
  invertBlocksOrIdentity(blocks);
}

void invertBlocksOrIdentity(std::span<Mat3> blocks) {
  for (Mat3& m : blocks) {
    const Real det = glm::determinant(m);
    m = std::isfinite(det) && std::abs(det) > 1e-300 ? glm::inverse(m) : Mat3(1.0);
  }
}

}  // namespace pba::cloth
