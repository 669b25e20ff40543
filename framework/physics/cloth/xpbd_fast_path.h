#pragma once
// CLOTH-2's fast path (docs/architecture.md §5, "Fast paths"): the XPBD sweep over the distance links
// that the cloth solver runs, once as the student's scalar route (CLOTH-2 per link) and once as the
// reference build's faster kernel. Both visit the links in their order and give the same results to
// the bit (tests/physics/cloth/cloth_xpbd_fast_path_test.cpp); in the hand-out the fast one runs the
// scalar one.
#include <array>
#include <span>

#include "physics/cloth/cloth.h"

namespace pba::cloth {

/// One Gauss–Seidel XPBD sweep over `links` in their order: CLOTH-2 (xpbdDistanceCorrection) per link with
/// the scaled compliance alphaTilde = α/h² of its kind, adding the corrections to x and Δλ to lambda
/// (one multiplier per link).
void sweepXpbdLinksScalar(std::span<const Link> links, const std::array<Real, kLinkKinds>& alphaTilde,
                          std::span<Vec3> x, std::span<const Real> w, std::span<Real> lambda);
/// The same sweep with the same results, faster (two links per instruction where consecutive links share
/// no particle). The hand-out runs sweepXpbdLinksScalar here.
void sweepXpbdLinksFast(std::span<const Link> links, const std::array<Real, kLinkKinds>& alphaTilde, std::span<Vec3> x,
                        std::span<const Real> w, std::span<Real> lambda);

}  // namespace pba::cloth
