#include "physics/cloth/xpbd_fast_path.h"

#include <cmath>

#include "physics/core/lanes.h"
#include "physics/exercises/not_implemented.h"  // the switch of the isolation build (student_release.sh)

namespace pba::cloth {

// Fast path of CLOTH-2: the scalar sweep pays per link one square root and four divisions (the direction
// r/l and Δλ), one after another along the chain of links that share particles. Two consecutive links
// that share no particle are independent in a Gauss–Seidel sweep (the second reads nothing the first
// writes), so they run together in the two lanes of a Pair: one divpd serves both. A link whose successor
// shares a particle runs alone (its lane 1 repeats it and is dropped). Every lane does CLOTH-2's IEEE
// operations in its order, and a skipped link (coincident particles, both pinned) adds +0 as the scalar
// route adds its zero correction, so the results are those of sweepXpbdLinksScalar to the bit.
// flatten: the lambda below inlines into the loop, as in relaxSticksFast.
[[gnu::flatten]] void sweepXpbdLinksFast(std::span<const Link> links, const std::array<Real, kLinkKinds>& alphaTilde,
                                         std::span<Vec3> x, std::span<const Real> w, std::span<Real> lambda) {
  // BEGIN SOLUTION
  constexpr Real kMinLength = 1e-12;  // [m] as CLOTH-2: coincident particles have no direction
  const std::size_t n = links.size();
  std::size_t k = 0;
  while (k < n) {
    const Link& a = links[k];
    const bool paired =
        k + 1 < n && links[k + 1].i != a.i && links[k + 1].i != a.j && links[k + 1].j != a.i && links[k + 1].j != a.j;
    const Link& b = paired ? links[k + 1] : a;
    const std::size_t kb = paired ? k + 1 : k;
    const Pair rx = Pair{x[a.i].x, x[b.i].x} - Pair{x[a.j].x, x[b.j].x};
    const Pair ry = Pair{x[a.i].y, x[b.i].y} - Pair{x[a.j].y, x[b.j].y};
    const Pair rz = Pair{x[a.i].z, x[b.i].z} - Pair{x[a.j].z, x[b.j].z};
    // glm::dot sums the products left to right; separate statements keep a contracting compiler from
    // fusing them differently from the scalar route.
    const Pair xx = rx * rx, yy = ry * ry, zz = rz * rz;
    const Pair d = xx + yy + zz;
    const Pair root = sqrtPair(d);
    const Real la = root[0], lb = root[1];
    const Pair wi{w[a.i], w[b.i]}, wj{w[a.j], w[b.j]};
    const Pair wSum = wi + wj;
    const bool skipA = la < kMinLength || wSum[0] == 0.0, skipB = lb < kMinLength || wSum[1] == 0.0;
    const Pair aT{alphaTilde[static_cast<std::size_t>(a.kind)], alphaTilde[static_cast<std::size_t>(b.kind)]};
    // A skipped lane divides by 1 instead (no trap on 0/0) and its result is dropped below.
    const Pair l{skipA ? 1.0 : la, skipB ? 1.0 : lb};
    const Pair denominator = wSum + aT;
    const Pair safeDenominator{skipA ? 1.0 : denominator[0], skipB ? 1.0 : denominator[1]};
    const Pair rest{a.restLength, b.restLength}, lam{lambda[k], lambda[kb]};
    const Pair dl = (-(l - rest) - aT * lam) / safeDenominator;
    const Pair nx = rx / l, ny = ry / l, nz = rz / l;
    const Pair si = wi * dl, sj = -wj * dl;
    const Pair ix = si * nx, iy = si * ny, iz = si * nz;
    const Pair jx = sj * nx, jy = sj * ny, jz = sj * nz;
    const auto apply = [&](const Link& link, std::size_t index, int lane, bool skip) {
      if (skip) {
        x[link.i] += Vec3(0.0);
        x[link.j] += Vec3(0.0);
        lambda[index] += 0.0;
        return;
      }
      x[link.i] += Vec3(ix[lane], iy[lane], iz[lane]);
      x[link.j] += Vec3(jx[lane], jy[lane], jz[lane]);
      lambda[index] += dl[lane];
    };
    apply(a, k, 0, skipA);
    if (paired) apply(b, kb, 1, skipB);
    k += paired ? 2 : 1;
  }
  // END SOLUTION
  // FAST PATH: CLOTH-2 (the hand-out runs the scalar sweep over your xpbdDistanceCorrection)
  // STUB: sweepXpbdLinksScalar(links, alphaTilde, x, w, lambda);
}

}  // namespace pba::cloth
