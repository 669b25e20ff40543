// FBX (binary 7.x) import against the file: a compact reader of the binary node records written here
// finds the Model objects of type "LimbNode" (the skeleton's joints), their parents from the
// Connections section and their "Lcl Translation/Rotation/Scaling" properties (Properties70). The
// model must hold those joints under their file parents with the same local transforms.
//
// Binary layout (Blender's public notes on the format, "FBX binary file format specification", and
// the FBX 7.x files themselves): a 27-byte header ("Kaydara FBX Binary  \0", 0x1A 0x00, uint32
// version), then node records: end offset, property count, property list length (uint32 before
// version 7500, uint64 from 7500), a name length byte and the name, the properties, nested records,
// and a null record that closes a nested list. A property is a type code followed by its value:
// Y int16, C bool, I int32, F float, D double, L int64, S/R length-prefixed bytes, and arrays
// f d l i b (uint32 count, encoding, byte length, then that many bytes: skipped, never inflated).
#include "graphics/model.h"
#include "model_file_check.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>

namespace {

namespace gfx = pba::graphics;
using namespace pba::testing::models;

struct FbxProperty {
  char type = 0;
  std::int64_t integer = 0;  ///< Y C I L
  double real = 0.0;         ///< F D
  std::string bytes;         ///< S R (arrays keep nothing)
};

struct FbxNode {
  std::string name;
  std::vector<FbxProperty> properties;
  std::vector<FbxNode> children;

  const FbxNode* child(const std::string& n) const {
    for (const FbxNode& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
};

class FbxBinaryReader {
 public:
  explicit FbxBinaryReader(std::string bytes) : d_(std::move(bytes)) {
    static const char kMagic[] = "Kaydara FBX Binary  ";
    if (d_.size() < 27 || d_.compare(0, sizeof(kMagic) - 1, kMagic) != 0) throw std::runtime_error("not a binary FBX");
    version_ = static_cast<std::uint32_t>(read<std::uint32_t>(23));
  }

  /// The top-level records, up to the null record that precedes the footer.
  std::vector<FbxNode> records() const {
    std::vector<FbxNode> top;
    std::size_t at = 27;
    while (at < d_.size()) {
      FbxNode node;
      if (!record(at, node)) break;
      top.push_back(std::move(node));
    }
    return top;
  }

 private:
  template <typename T>
  T read(std::size_t at) const {
    if (at + sizeof(T) > d_.size()) throw std::runtime_error("FBX record runs past the end of the file");
    T v;
    std::memcpy(&v, d_.data() + at, sizeof(T));  // the format is little-endian, as is the test machine
    return v;
  }
  /// Reads a T at p and moves p past it.
  template <typename T>
  T take(std::size_t& p) const {
    const T v = read<T>(p);
    p += sizeof(T);
    return v;
  }
  std::uint64_t readWord(std::size_t at) const {
    return version_ >= 7500 ? read<std::uint64_t>(at) : read<std::uint32_t>(at);
  }

  /// Reads the record at `at` into `node` and moves `at` past it; false at a null record.
  bool record(std::size_t& at, FbxNode& node) const {
    const std::size_t word = version_ >= 7500 ? 8 : 4;
    const std::uint64_t end = readWord(at), count = readWord(at + word), listLength = readWord(at + 2 * word);
    const std::size_t nameLength = read<std::uint8_t>(at + 3 * word);
    const std::size_t nameAt = at + 3 * word + 1;
    if (end == 0) {
      at = nameAt + nameLength;
      return false;
    }
    if (end > d_.size() || end <= at) throw std::runtime_error("FBX record end offset out of range");
    node.name = d_.substr(nameAt, nameLength);
    std::size_t p = nameAt + nameLength;
    for (std::uint64_t k = 0; k < count; ++k) node.properties.push_back(property(p));
    p = nameAt + nameLength + listLength;
    while (p < end) {
      FbxNode child;
      if (!record(p, child)) break;
      node.children.push_back(std::move(child));
    }
    at = static_cast<std::size_t>(end);
    return true;
  }

  FbxProperty property(std::size_t& p) const {
    FbxProperty prop;
    prop.type = take<char>(p);
    switch (prop.type) {
      case 'Y':
        prop.integer = take<std::int16_t>(p);
        break;
      case 'C':
        prop.integer = take<std::uint8_t>(p);
        break;
      case 'I':
        prop.integer = take<std::int32_t>(p);
        break;
      case 'L':
        prop.integer = take<std::int64_t>(p);
        break;
      case 'F':
        prop.real = take<float>(p);
        break;
      case 'D':
        prop.real = take<double>(p);
        break;
      case 'S':
      case 'R': {
        const std::uint32_t length = read<std::uint32_t>(p);
        if (p + 4 + length > d_.size()) throw std::runtime_error("FBX string runs past the end of the file");
        prop.bytes = d_.substr(p + 4, length);
        p += 4 + length;
        break;
      }
      case 'f':
      case 'd':
      case 'l':
      case 'i':
      case 'b':
        p += 12 + read<std::uint32_t>(p + 8);  // count, encoding, byte length; the data is skipped
        break;
      default:
        throw std::runtime_error(std::string("unknown FBX property type '") + prop.type + "'");
    }
    return prop;
  }

  std::string d_;
  std::uint32_t version_ = 0;
};

/// The values of a Properties70 "P" record: name, type, label, flags, then the values.
std::vector<double> p70Values(const FbxNode& model, const std::string& property, bool* found) {
  std::vector<double> values;
  *found = false;
  const FbxNode* p70 = model.child("Properties70");
  if (!p70) return values;
  for (const FbxNode& p : p70->children) {
    if (p.name != "P" || p.properties.empty() || p.properties[0].bytes != property) continue;
    *found = true;
    for (std::size_t k = 4; k < p.properties.size(); ++k) {
      const FbxProperty& v = p.properties[k];
      values.push_back(v.type == 'D' || v.type == 'F' ? v.real : static_cast<double>(v.integer));
    }
  }
  return values;
}

/// A property's values on the model, else on the file's property template for models (found = false
/// when neither has it).
std::vector<double> modelValues(const FbxNode& model, const FbxNode* modelTemplate, const std::string& property,
                                bool* found) {
  std::vector<double> v = p70Values(model, property, found);
  if (!*found && modelTemplate) v = p70Values(*modelTemplate, property, found);
  return v;
}

/// A vector property of the model or its template, else the FBX default (0 for translation and
/// rotation, 1 for scaling).
glm::dvec3 p70Vector(const FbxNode& model, const FbxNode* modelTemplate, const std::string& property,
                     glm::dvec3 fallback) {
  bool found = false;
  const std::vector<double> v = modelValues(model, modelTemplate, property, &found);
  return found && v.size() == 3 ? glm::dvec3(v[0], v[1], v[2]) : fallback;
}

/// Definitions > ObjectType "Model" > PropertyTemplate "FbxNode": the defaults of every Model.
const FbxNode* modelPropertyTemplate(const std::vector<FbxNode>& top) {
  for (const FbxNode& section : top) {
    if (section.name != "Definitions") continue;
    for (const FbxNode& type : section.children) {
      if (type.name != "ObjectType" || type.properties.empty() || type.properties[0].bytes != "Model") continue;
      for (const FbxNode& t : type.children)
        if (t.name == "PropertyTemplate" && !t.properties.empty() && t.properties[0].bytes == "FbxNode") return &t;
    }
  }
  return nullptr;
}

struct FbxSkeleton {
  std::vector<FileJoint> joints;         ///< LimbNode models, in file order
  std::vector<std::string> unsupported;  ///< joints whose transform needs pivots, offsets or pre/post rotations
};

/// Assimp names a node after its Model's name: the part before "\0\x01" ("Bone\0\x01Model").
FbxSkeleton readFbxSkeleton(const std::string& path) {
  const std::vector<FbxNode> top = FbxBinaryReader(readBytes(path)).records();
  std::map<std::int64_t, const FbxNode*> models;
  std::map<std::int64_t, std::int64_t> parentOf;
  for (const FbxNode& section : top) {
    if (section.name == "Objects")
      for (const FbxNode& o : section.children)
        if (o.name == "Model" && o.properties.size() >= 3) models[o.properties[0].integer] = &o;
    if (section.name == "Connections")
      for (const FbxNode& c : section.children)
        if (c.name == "C" && c.properties.size() >= 3 && c.properties[0].bytes == "OO")
          parentOf.emplace(c.properties[1].integer, c.properties[2].integer);
  }
  const auto nameOf = [](const FbxNode& m) {
    return m.properties[1].bytes.substr(0, m.properties[1].bytes.find('\0'));
  };
  const FbxNode* defaults = modelPropertyTemplate(top);
  FbxSkeleton s;
  for (const FbxNode& section : top) {
    if (section.name != "Objects") continue;
    for (const FbxNode& o : section.children) {
      if (o.name != "Model" || o.properties.size() < 3 || o.properties[2].bytes != "LimbNode") continue;
      FileJoint j;
      j.name = nameOf(o);
      const auto parent = parentOf.find(o.properties[0].integer);
      if (parent != parentOf.end() && models.count(parent->second)) j.parent = nameOf(*models[parent->second]);
      // With no pivots, offsets or pre/post rotations the FBX local transform is T·R·S, R from Euler
      // angles in degrees; rotation order XYZ (the default, RotationOrder 0) rotates about x first:
      // R = Rz·Ry·Rx for column vectors (FBX SDK, FbxNode "Computing transformation matrix").
      for (const char* p : {"RotationOffset", "RotationPivot", "ScalingOffset", "ScalingPivot", "PreRotation",
                            "PostRotation", "GeometricTranslation", "GeometricRotation", "GeometricScaling"}) {
        bool found = false;
        const std::vector<double> v = modelValues(o, defaults, p, &found);
        const bool neutral = std::string(p) == "GeometricScaling" ? v == std::vector<double>{1, 1, 1}
                                                                  : v == std::vector<double>{0, 0, 0};
        if (found && !neutral) s.unsupported.push_back(j.name + " (" + p + ")");
      }
      bool hasOrder = false;
      const std::vector<double> order = modelValues(o, defaults, "RotationOrder", &hasOrder);
      if (hasOrder && !order.empty() && order[0] != 0.0) s.unsupported.push_back(j.name + " (RotationOrder)");
      const glm::dvec3 t = p70Vector(o, defaults, "Lcl Translation", glm::dvec3(0.0));
      const glm::dvec3 r = glm::radians(p70Vector(o, defaults, "Lcl Rotation", glm::dvec3(0.0)));
      const glm::dvec3 sc = p70Vector(o, defaults, "Lcl Scaling", glm::dvec3(1.0));
      glm::dmat4 m = glm::translate(glm::dmat4(1.0), t);
      m = glm::rotate(m, r.z, glm::dvec3(0, 0, 1));
      m = glm::rotate(m, r.y, glm::dvec3(0, 1, 0));
      m = glm::rotate(m, r.x, glm::dvec3(1, 0, 0));
      j.local = glm::scale(m, sc);
      s.joints.push_back(j);
    }
  }
  return s;
}

/// Assimp splits an FBX transform with pivots or pre/post rotations into a chain of helper nodes
/// named "<joint>_$AssimpFbx$_<Part>" above the joint (AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, on by
/// default); the product of their locals is the file's local transform.
bool isAssimpFbxHelper(const std::string& name) { return name.find("_$AssimpFbx$_") != std::string::npos; }

// Binary FBX files of assimp-testmodels with a skeleton (spider.fbx, also binary, has no LimbNode).
const char* const kFbxFiles[] = {"FBX/animation_with_skeleton.fbx", "FBX/huesitos.fbx"};

}  // namespace

TEST(ModelImportFbx, LimbNodesAreNodesUnderTheirFileParentsWithTheirTransforms) {
  for (const char* file : kFbxFiles) {
    const std::string path = kAssimpModels + file;
    SCOPED_TRACE(path);
    const gfx::Model m = loadOrFail(path);
    if (m.nodes.empty()) continue;
    const FbxSkeleton s = readFbxSkeleton(path);
    ASSERT_GT(s.joints.size(), 1u);
    ASSERT_TRUE(s.unsupported.empty()) << "the test composes T·R·S only; this file needs more for "
                                       << s.unsupported.front();
    EXPECT_EQ(countNodesNamedLike(m, s.joints), static_cast<int>(s.joints.size()));
    expectJointsMatchTheFile(m, s.joints, isAssimpFbxHelper);
    ::testing::Test::RecordProperty(std::string("limb nodes ") + file, static_cast<int>(s.joints.size()));
  }
}

TEST(ModelImportFbx, NamedJointRestTranslationIsTheFiles) {
  const std::string path = kAssimpModels + "FBX/animation_with_skeleton.fbx";
  const gfx::Model m = loadOrFail(path);
  if (m.nodes.empty()) return;
  const FbxSkeleton s = readFbxSkeleton(path);
  // Bone.007 roots the second leg, off the armature's origin in x.
  const FileJoint* joint = findJoint(s.joints, "Bone.007");
  ASSERT_NE(joint, nullptr) << "the reader found no LimbNode Bone.007 in " << path;
  const glm::dvec3 file(joint->local[3]);
  ASSERT_GT(glm::length(file), 1.0) << "a translated joint makes the comparison meaningful";
  // No helper nodes above it in this file (no pivots), so the node's own local holds the translation.
  expectLocalTranslationNear(m, joint->name, file);
}

TEST(ModelImportFbx, TruncatedFileGivesAnErrorNamingThePath) {
  expectTruncatedCopyFails(kAssimpModels + "FBX/animation_with_skeleton.fbx");
}
