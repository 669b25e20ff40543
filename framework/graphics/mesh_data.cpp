// Unit primitive generators (see mesh_data.h for their object-space conventions).
#include "graphics/mesh_data.h"

#include <glm/gtc/constants.hpp>

namespace pba::graphics {
namespace {

std::uint32_t vertexCount(const MeshData& m) { return static_cast<std::uint32_t>(m.positions.size()); }

/// Adds a lat-long band of vertices between polar angles [theta0, theta1] of a sphere of `radius`
/// centred at (0, yOffset, 0), with `stacks` rows; returns the first vertex index.
void addSphereBand(MeshData& m, float radius, float yOffset, float theta0, float theta1, int slices, int stacks) {
  const std::uint32_t base = vertexCount(m);
  for (int i = 0; i <= stacks; ++i) {
    const float theta = theta0 + (theta1 - theta0) * static_cast<float>(i) / static_cast<float>(stacks);
    for (int j = 0; j <= slices; ++j) {
      const float phi = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(slices);
      const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(radius * n + glm::vec3(0.0f, yOffset, 0.0f));
      m.normals.push_back(n);
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const std::uint32_t a = base + static_cast<std::uint32_t>(i) * row + static_cast<std::uint32_t>(j);
      const std::uint32_t b = a + row;
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
}

/// Open tube of radius 1 between y0 and y1 (scaled by radius r).
void addTube(MeshData& m, float r, float y0, float y1, int slices) {
  const std::uint32_t base = vertexCount(m);
  for (int j = 0; j <= slices; ++j) {
    const float phi = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(slices);
    const glm::vec3 n(std::sin(phi), 0.0f, std::cos(phi));
    m.positions.push_back(r * n + glm::vec3(0.0f, y0, 0.0f));
    m.normals.push_back(n);
    m.positions.push_back(r * n + glm::vec3(0.0f, y1, 0.0f));
    m.normals.push_back(n);
  }
  for (int j = 0; j < slices; ++j) {
    const std::uint32_t a = base + 2u * static_cast<std::uint32_t>(j);
    m.indices.insert(m.indices.end(), {a, a + 2, a + 1, a + 1, a + 2, a + 3});
  }
}

/// Disc of radius 1 at height y facing +y (up = true) or -y.
void addDisc(MeshData& m, float y, bool up, int slices) {
  const std::uint32_t centre = vertexCount(m);
  const glm::vec3 n(0.0f, up ? 1.0f : -1.0f, 0.0f);
  m.positions.emplace_back(0.0f, y, 0.0f);
  m.normals.push_back(n);
  for (int j = 0; j <= slices; ++j) {
    const float phi = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(slices);
    m.positions.emplace_back(std::sin(phi), y, std::cos(phi));
    m.normals.push_back(n);
  }
  for (int j = 0; j < slices; ++j) {
    const std::uint32_t a = centre + 1u + static_cast<std::uint32_t>(j);
    if (up) {
      m.indices.insert(m.indices.end(), {centre, a, a + 1});
    } else {
      m.indices.insert(m.indices.end(), {centre, a + 1, a});
    }
  }
}

}  // namespace

void MeshData::append(const MeshData& other) {
  const std::uint32_t base = vertexCount(*this);
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

MeshData makeBox() {
  MeshData m;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(sign);
      const glm::vec3 u = glm::vec3(n[1], n[2], n[0]);  // a perpendicular axis
      const glm::vec3 v = glm::cross(n, u);             // u x v = n: counter-clockwise seen from outside
      const std::uint32_t base = vertexCount(m);
      const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const glm::vec2& c : corners) {
        m.positions.push_back(n + c.x * u + c.y * v);
        m.normals.push_back(n);
      }
      m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  return m;
}

MeshData makeSphere(int slices, int stacks) {
  MeshData m;
  addSphereBand(m, 1.0f, 0.0f, 0.0f, glm::pi<float>(), slices, stacks);
  return m;
}

MeshData makeCylinder(int slices, bool caps) {
  MeshData m;
  addTube(m, 1.0f, 0.0f, 1.0f, slices);
  if (caps) {
    addDisc(m, 0.0f, false, slices);
    addDisc(m, 1.0f, true, slices);
  }
  return m;
}

MeshData makeCone(int slices) {
  MeshData m;
  // Side: slope normal of a cone of radius 1 and height 1 is (cos, 1, sin)/sqrt(2) in the radial frame.
  for (int j = 0; j < slices; ++j) {
    const float phi0 = glm::two_pi<float>() * static_cast<float>(j) / static_cast<float>(slices);
    const float phi1 = glm::two_pi<float>() * static_cast<float>(j + 1) / static_cast<float>(slices);
    const float phiMid = 0.5f * (phi0 + phi1);
    const std::uint32_t base = vertexCount(m);
    m.positions.emplace_back(std::sin(phi0), 0.0f, std::cos(phi0));
    m.normals.push_back(glm::normalize(glm::vec3(std::sin(phi0), 1.0f, std::cos(phi0))));
    m.positions.emplace_back(std::sin(phi1), 0.0f, std::cos(phi1));
    m.normals.push_back(glm::normalize(glm::vec3(std::sin(phi1), 1.0f, std::cos(phi1))));
    m.positions.emplace_back(0.0f, 1.0f, 0.0f);
    m.normals.push_back(glm::normalize(glm::vec3(std::sin(phiMid), 1.0f, std::cos(phiMid))));
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
  }
  addDisc(m, 0.0f, false, slices);
  return m;
}

MeshData makePlane() {
  MeshData m;
  m.positions = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

MeshData makeCapsule(float radius, float halfLength, int slices, int stacks) {
  MeshData m;
  const int hemi = stacks / 2 > 0 ? stacks / 2 : 1;
  addSphereBand(m, radius, halfLength, 0.0f, glm::half_pi<float>(), slices, hemi);
  addTube(m, radius, -halfLength, halfLength, slices);
  addSphereBand(m, radius, -halfLength, glm::half_pi<float>(), glm::pi<float>(), slices, hemi);
  return m;
}

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = positions[indices[t]];
    const glm::vec3& b = positions[indices[t + 1]];
    const glm::vec3& c = positions[indices[t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);  // length = 2 * area: area weighting
    for (int k = 0; k < 3; ++k) normals[indices[t + static_cast<std::size_t>(k)]] += n;
  }
  for (glm::vec3& n : normals) {
    const float len = glm::length(n);
    n = len > 1e-20f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return normals;
}

}  // namespace pba::graphics
