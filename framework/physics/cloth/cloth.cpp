#include "physics/cloth/cloth.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/cloth/topology.h"
#include "physics/core/validate.h"

namespace pba::cloth {
namespace {

constexpr int kMaxResolution = 1024;  // particles per side: 10⁶ particles at most
constexpr Real kMaxStiffness = 1e9;   // [N/m]
constexpr Real kMaxCompliance = 1e6;  // [m/N]

Status checkNonNegative(const std::string& field, Real value, Real hi) { return checkRange(field, value, 0.0, hi); }

void refreshInverseMasses(Cloth& cloth) {
  cloth.inverseMass.resize(cloth.size());
  for (std::size_t i = 0; i < cloth.size(); ++i) cloth.inverseMass[i] = cloth.mass[i] > 0.0 ? 1.0 / cloth.mass[i] : 0.0;
  for (const Pin& p : cloth.pins) cloth.inverseMass[p.particle] = 0.0;
}

std::vector<std::uint32_t> gridPinned(const GridDesc& d) {
  const auto nx = static_cast<std::uint32_t>(d.resolutionX);
  switch (d.pins) {
    case GridPins::None:
      return {};
    case GridPins::TopCorners:
      return {0, nx - 1};
    case GridPins::TopCornersAndMiddle:
      return {0, (nx - 1) / 2, nx - 1};
    case GridPins::TopRow: {
      std::vector<std::uint32_t> row(nx);
      for (std::uint32_t i = 0; i < nx; ++i) row[i] = i;
      return row;
    }
  }
  return {};
}

Result<Cloth> assemble(const TriangleMesh& mesh, const ClothMaterial& material, std::span<const std::uint32_t> pinned,
                       int gridX, int gridY, SpringLayout layout) {
  if (Status s = validateMesh(mesh); !s) return Error{s.error()};
  if (Status s = validate(material); !s) return Error{"material." + s.error()};
  Cloth cloth;
  cloth.position = mesh.vertices;
  cloth.restPosition = mesh.vertices;
  cloth.velocity.assign(mesh.vertices.size(), Vec3(0.0));
  cloth.triangles = mesh.triangles;
  cloth.material = material;
  cloth.gridX = gridX;
  cloth.gridY = gridY;
  cloth.layout = layout;
  for (std::uint32_t p : pinned) {
    if (p >= mesh.vertices.size()) return Error{"pins: particle " + std::to_string(p) + " out of range"};
    pin(cloth, p, mesh.vertices[p]);
  }
  rebuildTopology(cloth);
  return cloth;
}

}  // namespace

Status validate(const ClothMaterial& m) {
  if (Status s = checkPositive("massPerArea", m.massPerArea); !s) return s;
  if (Status s = checkNonNegative("stretchStiffness", m.stretchStiffness, kMaxStiffness); !s) return s;
  if (Status s = checkNonNegative("shearStiffness", m.shearStiffness, kMaxStiffness); !s) return s;
  if (Status s = checkNonNegative("bendStiffness", m.bendStiffness, kMaxStiffness); !s) return s;
  if (Status s = checkNonNegative("springDamping", m.springDamping, kMaxStiffness); !s) return s;
  if (Status s = checkNonNegative("stretchCompliance", m.stretchCompliance, kMaxCompliance); !s) return s;
  if (Status s = checkNonNegative("shearCompliance", m.shearCompliance, kMaxCompliance); !s) return s;
  if (Status s = checkNonNegative("bendCompliance", m.bendCompliance, kMaxCompliance); !s) return s;
  if (Status s = checkNonNegative("bendLinkCompliance", m.bendLinkCompliance, kMaxCompliance); !s) return s;
  return checkNonNegative("thickness", m.thickness, 1.0);
}

Status validate(const GridDesc& d) {
  if (d.resolutionX < 2 || d.resolutionX > kMaxResolution) {
    return Error{"resolutionX: must be in [2, " + std::to_string(kMaxResolution) + "], got " +
                 std::to_string(d.resolutionX)};
  }
  if (d.resolutionY < 2 || d.resolutionY > kMaxResolution) {
    return Error{"resolutionY: must be in [2, " + std::to_string(kMaxResolution) + "], got " +
                 std::to_string(d.resolutionY)};
  }
  if (Status s = checkPositive("width", d.width); !s) return s;
  if (Status s = checkPositive("height", d.height); !s) return s;
  if (Status s = checkFinite("center", d.center); !s) return s;
  const Real lu = glm::length(d.axisU), lv = glm::length(d.axisV);
  if (!isFinite(d.axisU) || std::abs(lu - 1.0) > 1e-9) return Error{"axisU: must be a unit vector"};
  if (!isFinite(d.axisV) || std::abs(lv - 1.0) > 1e-9) return Error{"axisV: must be a unit vector"};
  if (std::abs(glm::dot(d.axisU, d.axisV)) > 1e-9) return Error{"axisV: must be perpendicular to axisU"};
  return Status::success();
}

TriangleMesh gridMesh(const GridDesc& d) {
  TriangleMesh mesh;
  const int nx = d.resolutionX, ny = d.resolutionY;
  mesh.vertices.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Real u = static_cast<Real>(i) / (nx - 1) - 0.5, v = static_cast<Real>(j) / (ny - 1) - 0.5;
      mesh.vertices.push_back(d.center + u * d.width * d.axisU + v * d.height * d.axisV);
    }
  }
  auto index = [nx](int i, int j) { return static_cast<std::uint32_t>(j * nx + i); };
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), e = index(i, j + 1);
      const bool flip = d.diagonals == GridDiagonals::Alternating && (i + j) % 2 == 1;
      // Counter-clockwise seen from the side û × v̂ points to.
      if (!flip) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, e});
      } else {
        mesh.triangles.push_back({a, b, e});
        mesh.triangles.push_back({b, c, e});
      }
    }
  }
  return mesh;
}

Real Cloth::totalMass() const {
  Real m = 0.0;
  for (Real mi : mass) m += mi;
  return m;
}

Result<Cloth> buildCloth(const TriangleMesh& mesh, const ClothMaterial& material,
                         std::span<const std::uint32_t> pinned) {
  return assemble(mesh, material, pinned, 0, 0, SpringLayout::Mesh);
}

Result<Cloth> buildClothGrid(const GridDesc& desc, const ClothMaterial& material) {
  if (Status s = validate(desc); !s) return Error{s.error()};
  const std::vector<std::uint32_t> pinned = gridPinned(desc);
  return assemble(gridMesh(desc), material, pinned, desc.resolutionX, desc.resolutionY, desc.layout);
}

void rebuildTopology(Cloth& cloth) {
  cloth.edges = buildEdges(cloth.triangles);
  cloth.constraints = edgeConstraints(cloth.edges, cloth.restPosition, cloth.gridX);
  if (cloth.layout == SpringLayout::Grid && cloth.gridX > 0) {
    cloth.springs = gridSprings(gridSpringTopology(cloth.gridX, cloth.gridY), cloth.restPosition);
  } else {
    cloth.springs = meshSprings(cloth.edges, cloth.restPosition, cloth.gridX);
  }
  cloth.bending = bendingStencils(cloth.edges, cloth.restPosition);
  // Bending links are all of kind Bend (even across a quad's diagonal): as rigid shear constraints the
  // other diagonals would forbid folding along the diagonals and fight the stretch constraints.
  cloth.bendLinks = acrossEdgeLinks(cloth.edges, cloth.restPosition, 0);
  orderByColour(cloth.constraints, cloth.size());
  orderByColour(cloth.bendLinks, cloth.size());
  orderByColour(cloth.bending, cloth.size());
  cloth.mass = lumpedMasses(cloth.triangles, cloth.restPosition, cloth.material.massPerArea, cloth.size());
  refreshInverseMasses(cloth);
}

Pin* findPin(Cloth& cloth, std::uint32_t particle) {
  for (Pin& p : cloth.pins) {
    if (p.particle == particle) return &p;
  }
  return nullptr;
}

void pin(Cloth& cloth, std::uint32_t particle, const Vec3& target) {
  if (Pin* p = findPin(cloth, particle)) {
    p->target = target;
  } else {
    cloth.pins.push_back({particle, target});
  }
  if (particle < cloth.inverseMass.size()) cloth.inverseMass[particle] = 0.0;
}

void unpin(Cloth& cloth, std::uint32_t particle) {
  std::erase_if(cloth.pins, [particle](const Pin& p) { return p.particle == particle; });
  if (particle < cloth.inverseMass.size() && cloth.mass[particle] > 0.0)
    cloth.inverseMass[particle] = 1.0 / cloth.mass[particle];
}

std::optional<std::string> describeNonFinite(const Cloth& cloth) {
  for (std::size_t i = 0; i < cloth.size(); ++i) {
    if (!isFinite(cloth.position[i])) return "cloth particle " + std::to_string(i) + " position is not finite";
    if (!isFinite(cloth.velocity[i])) return "cloth particle " + std::to_string(i) + " velocity is not finite";
  }
  return std::nullopt;
}

}  // namespace pba::cloth
