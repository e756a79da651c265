#include "runtime/MeshFile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "compiler/common/InputFile.h"
#include "runtime/Camera.h"
#include "runtime/Tangents.h"

namespace mxc::rt {

namespace {

/// A mesh file, or a buffer a .gltf names, larger than this is refused.
constexpr size_t kMaxMeshBytes = size_t{2} << 30;

/// Unit face normal of a triangle, or nullopt when it has no area.
std::optional<glm::vec3> faceNormal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float length = glm::length(n);
  if (!(length > 1e-30f)) return std::nullopt;
  return n / length;  // length > 0
}

/// Unit normal from a sum, or +y when the sum vanishes (a vertex of degenerate faces only).
glm::vec3 unitOr(glm::vec3 sum, glm::vec3 fallback) {
  const float length = glm::length(sum);
  return length > 1e-30f ? sum / length : fallback;  // length > 0
}

/// Every triangle gets its own three vertices with the face's normal (glTF 2.0 spec, 3.7.2.1).
void makeFlat(Mesh& mesh) {
  Mesh flat;
  flat.vertices.reserve(mesh.indices.size());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    Vertex v[3] = {mesh.vertices[mesh.indices[i]], mesh.vertices[mesh.indices[i + 1]], mesh.vertices[mesh.indices[i + 2]]};
    const glm::vec3 n = faceNormal(v[0].position, v[1].position, v[2].position).value_or(glm::vec3(0, 1, 0));
    for (Vertex& x : v) {
      x.normal = n;
      flat.indices.push_back(static_cast<uint32_t>(flat.vertices.size()));
      flat.vertices.push_back(x);
    }
  }
  mesh = std::move(flat);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// Why a loaded mesh cannot be rendered, positions first: a position that is NaN or infinite,
/// positions beyond what the shaders' 32-bit floats take (runtime/Camera.h; the normals and
/// tangents computed from such positions overflow too: a 1e10 triangle's edges cross to 1e20,
/// whose squared length is inf), then any other value that is NaN or infinite. Each value is
/// tested alone: a sum of finite values can overflow.
std::optional<std::string> valueProblem(const Mesh& mesh) {
  float reach = 0.0f;
  for (const Vertex& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(v.position[k])) return std::string("the mesh holds NaN or infinite positions");
      reach = std::max(reach, std::abs(v.position[k]));
    }
  }
  if (reach > kLargestSceneRadius) {
    return fmt::format("the mesh reaches {:g} units from the origin, and mxc renders meshes within {:g} (the shaders "
                       "compute in 32-bit floats): scale it down",
                       double(reach), double(kLargestSceneRadius));
  }
  for (const Vertex& v : mesh.vertices) {
    const float values[] = {v.normal.x, v.normal.y, v.normal.z, v.uv.x, v.uv.y, v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w};
    for (float value : values) {
      if (!std::isfinite(value)) return std::string("the mesh holds NaN or infinite normals, tangents or texture coordinates");
    }
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// glTF

/// tinygltf's file access, through readInputFile: a buffer URI naming a FIFO or /dev/zero is
/// refused instead of blocking or filling memory; nothing is ever written.
// Anything that exists "exists" for tinygltf, so that reading it says why it cannot be read (a
// FIFO, a folder, /dev/zero) rather than tinygltf's "File not found".
bool gltfFileExists(const std::string& path, void*) {
  const auto problem = inputFileProblem(path);
  return !problem || *problem != "it does not exist";
}
// tinygltf joins the file's folder and a buffer's URI with a '/': an absolute URI ("/dev/zero",
// a path reference of RFC 3986, s. 4.2) gives "folder//dev/zero", which names a file under the
// folder. The folder is passed normalised (no "//" of its own), so a "//" is where the URI starts.
std::string gltfExpandPath(const std::string& path, void*) {
  const size_t absolute = path.find("//");
  return absolute == std::string::npos ? path : path.substr(absolute + 1);
}
bool gltfReadFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  auto bytes = readInputFile(path, kMaxMeshBytes);
  if (auto* why = std::get_if<1>(&bytes)) {
    if (err) *err += fmt::format("cannot read '{}': {}\n", path, *why);
    return false;
  }
  const std::string& data = std::get<0>(bytes);
  out->assign(data.begin(), data.end());
  return true;
}
bool gltfRefuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "mxc does not write glTF files\n";
  return false;
}
/// Images are not decoded: the material's textures come from its document.
bool gltfSkipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

/// Where an accessor's elements lie in its buffer: the first, and the distance between two.
struct Elements {
  const unsigned char* first = nullptr;
  size_t stride = 0;
};

/// Locates the elements of accessor `index` (`a`), each `elementBytes` long, after checking
/// that it has a buffer view, that the view has a buffer, and that the last element ends inside
/// the view and the view inside its buffer (written so that no sum can overflow). Without a
/// buffer view an accessor is all zeros (or sparse, refused by the callers): no geometry, and
/// its count is bounded by nothing, so it is refused before anything is allocated. `what`
/// names the accessor in messages ("accessor", "index accessor").
std::variant<Elements, std::string> locate(const tinygltf::Model& model, int index, const tinygltf::Accessor& a,
                                           size_t elementBytes, const char* what) {
  if (a.bufferView < 0) return fmt::format("{} {} has no buffer view", what, index);
  if (size_t(a.bufferView) >= model.bufferViews.size()) return fmt::format("{} {}: no buffer view {}", what, index, a.bufferView);
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) return fmt::format("buffer view {}: no buffer {}", a.bufferView, view.buffer);
  const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
  const size_t stride = view.byteStride ? view.byteStride : elementBytes;  // >= 1: elementBytes >= 1
  bool fits = true;
  if (a.count > 0) {
    fits = view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset &&
           a.byteOffset <= view.byteLength && elementBytes <= view.byteLength - a.byteOffset &&
           (a.count - 1) <= (view.byteLength - a.byteOffset - elementBytes) / stride;
  }
  if (!fits) return fmt::format("{} {} reaches past the end of its buffer", what, index);
  return Elements{data.data() + view.byteOffset + a.byteOffset, stride};
}

/// Reads accessor `index` as `components` floats per element into `out` (FLOAT, or the
/// normalised integer types of glTF 2.0 spec 3.11 "normalized" with their decoding formulas).
std::optional<std::string> readFloats(const tinygltf::Model& model, int index, int components, std::vector<float>& out) {
  if (index < 0 || size_t(index) >= model.accessors.size()) return fmt::format("accessor {} does not exist", index);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse) return fmt::format("accessor {} is sparse, which mxc does not read", index);
  if (tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) != components) {
    return fmt::format("accessor {} has {} components per element, expected {}", index,
                       tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)), components);
  }
  const int componentBytes = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  if (componentBytes <= 0) return fmt::format("accessor {} has an unknown component type {}", index, a.componentType);
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized) {
    return fmt::format("accessor {} holds integers that are not normalized", index);
  }
  auto located = locate(model, index, a, size_t(componentBytes) * size_t(components), "accessor");
  if (auto* why = std::get_if<std::string>(&located)) return *why;
  const auto [base, stride] = std::get<Elements>(located);
  out.assign(a.count * size_t(components), 0.0f);  // a.count elements fit in the buffer: bounded
  for (size_t e = 0; e < a.count; ++e) {
    const unsigned char* element = base + e * stride;
    for (int c = 0; c < components; ++c) {
      const unsigned char* p = element + size_t(c) * size_t(componentBytes);
      float v = 0.0f;
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&v, p, 4); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = float(*p) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: v = std::max(float(int8_t(*p)) / 127.0f, -1.0f); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, p, 2); v = float(s) / 65535.0f; break; }
        case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t s; std::memcpy(&s, p, 2); v = std::max(float(s) / 32767.0f, -1.0f); break; }
        default: return fmt::format("accessor {}: component type {} cannot hold this attribute", index, a.componentType);
      }
      out[e * size_t(components) + size_t(c)] = v;
    }
  }
  return std::nullopt;
}

/// Reads an index accessor (unsigned byte, short or int; glTF 2.0 spec 3.7.2.1).
std::optional<std::string> readIndices(const tinygltf::Model& model, int index, std::vector<uint32_t>& out) {
  if (index < 0 || size_t(index) >= model.accessors.size()) return fmt::format("accessor {} does not exist", index);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse) return fmt::format("accessor {} is sparse, which mxc does not read", index);
  if (a.type != TINYGLTF_TYPE_SCALAR) return fmt::format("index accessor {} is not scalar", index);
  const int bytes = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    return fmt::format("index accessor {} is not of an unsigned integer type", index);
  }
  auto located = locate(model, index, a, size_t(bytes), "index accessor");
  if (auto* why = std::get_if<std::string>(&located)) return *why;
  const auto [base, stride] = std::get<Elements>(located);
  out.assign(a.count, 0);  // a.count indices fit in the buffer: bounded
  for (size_t e = 0; e < a.count; ++e) {
    const unsigned char* p = base + e * stride;
    if (bytes == 1) {
      out[e] = *p;
    } else if (bytes == 2) {
      uint16_t s;
      std::memcpy(&s, p, 2);
      out[e] = s;
    } else {
      std::memcpy(&out[e], p, 4);
    }
  }
  return std::nullopt;
}

/// A node's local transform: its matrix, else translation * rotation * scale (glTF 2.0 spec,
/// 3.5.3).
glm::dmat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glTF
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4) {
    // glTF stores x, y, z, w; glm's constructor takes w first.
    m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

/// Triangle corner indices of a primitive from its mode (lists, strips, fans; glTF 2.0 spec
/// 3.7.2.1), in counter-clockwise order.
std::vector<uint32_t> triangles(int mode, const std::vector<uint32_t>& order) {
  std::vector<uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLES || mode == -1) {
    out.assign(order.begin(), order.begin() + long(order.size() / 3 * 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < order.size(); ++i) {
      // Every second triangle of a strip is wound the other way.
      if (i % 2 == 0) out.insert(out.end(), {order[i], order[i + 1], order[i + 2]});
      else out.insert(out.end(), {order[i + 1], order[i], order[i + 2]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 1; i + 1 < order.size(); ++i) out.insert(out.end(), {order[0], order[i], order[i + 1]});
  }
  return out;
}

/// One primitive in world space, its normals and tangents complete.
std::variant<Mesh, std::string> readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                              const glm::dmat4& toWorld) {
  auto attribute = [&](const char* name) {
    auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
  };
  std::vector<float> positions, normals, uvs, tangents;
  if (attribute("POSITION") < 0) return std::string("a primitive has no POSITION");
  if (auto why = readFloats(model, attribute("POSITION"), 3, positions)) return *why;
  const size_t count = positions.size() / 3;
  if (count > size_t{1} << 31) return std::string("a primitive has more than 2^31 vertices");
  auto sized = [&](std::vector<float>& values, size_t components, const char* name) -> std::optional<std::string> {
    if (values.size() != count * components) return fmt::format("{} has {} elements, POSITION {}", name, values.size() / components, count);
    return std::nullopt;
  };
  if (attribute("NORMAL") >= 0) {
    if (auto why = readFloats(model, attribute("NORMAL"), 3, normals)) return *why;
    if (auto why = sized(normals, 3, "NORMAL")) return *why;
  }
  if (attribute("TEXCOORD_0") >= 0) {
    if (auto why = readFloats(model, attribute("TEXCOORD_0"), 2, uvs)) return *why;
    if (auto why = sized(uvs, 2, "TEXCOORD_0")) return *why;
  }
  if (attribute("TANGENT") >= 0 && !normals.empty()) {  // tangents without normals are ignored (3.7.2.1)
    if (auto why = readFloats(model, attribute("TANGENT"), 4, tangents)) return *why;
    if (auto why = sized(tangents, 4, "TANGENT")) return *why;
  }
  std::vector<uint32_t> order;
  if (primitive.indices >= 0) {
    if (auto why = readIndices(model, primitive.indices, order)) return *why;
    for (uint32_t i : order) {
      if (i >= count) return fmt::format("index {} of accessor {} is past the {} vertices", i, primitive.indices, count);
    }
  } else {
    order.resize(count);
    for (size_t i = 0; i < count; ++i) order[i] = uint32_t(i);
  }
  Mesh mesh;
  mesh.indices = triangles(primitive.mode, order);
  const glm::dmat3 linear(toWorld);
  const double det = glm::determinant(linear);
  // A mirroring transform turns counter-clockwise faces clockwise (glTF 2.0 spec, 3.7.1).
  if (det < 0.0) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
  // Normals by the inverse transpose; a singular transform (a zero scale) flattens the mesh,
  // and its normals are then left as the file gives them.
  const glm::dmat3 normalMatrix = std::abs(det) > 1e-300 ? glm::transpose(glm::inverse(linear)) : glm::dmat3(1.0);
  mesh.vertices.resize(count);
  for (size_t v = 0; v < count; ++v) {
    Vertex& x = mesh.vertices[v];
    x.position = glm::vec3(toWorld * glm::dvec4(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1.0));
    if (!normals.empty()) {
      x.normal = unitOr(glm::vec3(normalMatrix * glm::dvec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2])), glm::vec3(0, 1, 0));
    }
    // glTF's v runs down the image; MaterialX's (and this renderer's) up.
    if (!uvs.empty()) x.uv = glm::vec2(uvs[2 * v], 1.0f - uvs[2 * v + 1]);
    if (!tangents.empty()) {
      const glm::vec3 t = glm::vec3(linear * glm::dvec3(tangents[4 * v], tangents[4 * v + 1], tangents[4 * v + 2]));
      // The flip of v leaves the bitangent's direction (image up) unchanged; a mirror flips it.
      const float w = (tangents[4 * v + 3] < 0.0f ? -1.0f : 1.0f) * (det < 0.0 ? -1.0f : 1.0f);
      glm::vec3 unit = t - x.normal * glm::dot(x.normal, t);
      const float length = glm::length(unit);
      unit = length > 1e-30f ? unit / length : glm::vec3(0.0f);  // length > 0; zero marks "compute"
      x.tangent = glm::vec4(unit, w);
    }
  }
  if (normals.empty()) makeFlat(mesh);
  bool missingTangent = tangents.empty();
  for (const Vertex& x : mesh.vertices) missingTangent = missingTangent || glm::vec3(x.tangent) == glm::vec3(0.0f);
  if (missingTangent) generateTangents(mesh);
  return mesh;
}

std::variant<Mesh, std::string> loadGltf(const std::filesystem::path& path, const std::string& bytes, bool binary) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&gltfSkipImage, nullptr);
  loader.SetFsCallbacks({&gltfFileExists, &gltfExpandPath, &gltfReadFile, &gltfRefuseWrite, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const std::string base = path.parent_path().empty() ? std::string(".") : path.parent_path().lexically_normal().string();
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned int>(bytes.size()), base)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), base);
  auto trimmed = [](std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    for (char& c : s) c = c == '\n' ? ';' : c;
    return s;
  };
  if (!ok) return fmt::format("{}: {}", path.string(), err.empty() ? std::string("not a glTF 2.0 file") : trimmed(err));

  // The node hierarchy, each node once (a node has at most one parent: glTF 2.0 spec, 3.5.1).
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const size_t scene = model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? size_t(model.defaultScene) : 0;
    roots = model.scenes[scene].nodes;
  } else {
    std::vector<bool> child(model.nodes.size(), false);
    for (const tinygltf::Node& n : model.nodes) {
      for (int c : n.children) {
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
      }
    }
    for (size_t n = 0; n < model.nodes.size(); ++n) {
      if (!child[n]) roots.push_back(int(n));
    }
  }
  Mesh out;
  std::vector<bool> visited(model.nodes.size(), false);
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
  while (!stack.empty()) {
    auto [index, parent] = stack.back();
    stack.pop_back();
    if (index < 0 || size_t(index) >= model.nodes.size()) return fmt::format("{}: node {} does not exist", path.string(), index);
    if (visited[size_t(index)]) return fmt::format("{}: node {} appears twice in the hierarchy", path.string(), index);
    visited[size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    const glm::dmat4 toWorld = parent * localTransform(node);
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model.meshes.size()) return fmt::format("{}: node {}: mesh {} does not exist", path.string(), index, node.mesh);
      const tinygltf::Mesh& gltfMesh = model.meshes[size_t(node.mesh)];
      // The node is a part, named as MaterialX's viewer names geometry: the node's name, else its
      // mesh's.
      MeshPart part;
      part.name = !node.name.empty() ? node.name : !gltfMesh.name.empty() ? gltfMesh.name : fmt::format("node{}", index);
      part.firstIndex = static_cast<uint32_t>(out.indices.size());
      for (size_t p = 0; p < gltfMesh.primitives.size(); ++p) {
        auto read = readPrimitive(model, gltfMesh.primitives[p], toWorld);
        if (auto* why = std::get_if<std::string>(&read)) {
          return fmt::format("{}: mesh {} ('{}') primitive {}: {}", path.string(), node.mesh, gltfMesh.name, p, *why);
        }
        const Mesh& piece = std::get<Mesh>(read);
        if (out.vertices.size() + piece.vertices.size() > size_t{1} << 31) return fmt::format("{}: more than 2^31 vertices", path.string());
        const uint32_t offset = static_cast<uint32_t>(out.vertices.size());
        out.vertices.insert(out.vertices.end(), piece.vertices.begin(), piece.vertices.end());
        for (uint32_t i : piece.indices) out.indices.push_back(offset + i);
      }
      part.indexCount = static_cast<uint32_t>(out.indices.size()) - part.firstIndex;
      if (part.indexCount > 0) out.parts.push_back(std::move(part));
    }
    for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.emplace_back(*c, toWorld);
  }
  if (out.indices.empty()) return fmt::format("{}: the file has no triangles in its scene", path.string());
  return out;
}

// ---------------------------------------------------------------------------------------------
// OBJ

/// Numbers of an OBJ file that tinyobjloader would misread: `v nan` and `v inf` (and a value
/// beyond a float's range) it reads as 0, and a face index beyond an int's range wraps (to -1,
/// a valid relative index). Checked here, with the line and column, before it parses.
std::optional<std::string> objNumberProblem(const std::filesystem::path& path, std::string_view text) {
  size_t lineNo = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    ++lineNo;
    start = end + 1;
    size_t i = 0;
    auto skipBlank = [&] {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    };
    auto token = [&] {
      const size_t from = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
      return line.substr(from, i - from);
    };
    skipBlank();
    const std::string_view keyword = token();
    const bool vertexData = keyword == "v" || keyword == "vn" || keyword == "vt";
    const bool face = keyword == "f" || keyword == "l" || keyword == "p";
    if (!vertexData && !face) continue;
    for (;;) {
      skipBlank();
      if (i >= line.size() || line[i] == '#') break;
      const size_t column = i + 1;
      const std::string_view word = token();
      auto where = [&] { return fmt::format("{}:{}:{}", path.string(), lineNo, column); };
      if (vertexData) {
        // strtod reads nan, inf and 1e400 (as inf) as they are: what must be refused.
        const std::string copy(word);
        char* stop = nullptr;
        const double v = std::strtod(copy.c_str(), &stop);
        if (stop != copy.c_str() && !std::isfinite(static_cast<float>(v))) {
          return fmt::format("{}: '{}' is not a finite number (a vertex's values must be)", where(), word);
        }
        continue;
      }
      // v, v/vt, v//vn, v/vt/vn: each present index an integer an int holds.
      for (size_t from = 0; from <= word.size();) {
        size_t slash = word.find('/', from);
        if (slash == std::string_view::npos) slash = word.size();
        const std::string_view part = word.substr(from, slash - from);
        if (!part.empty()) {
          long long value = 0;
          const std::errc ec = std::from_chars(part.data(), part.data() + part.size(), value).ec;
          const bool fits = value <= std::numeric_limits<int>::max() && value >= std::numeric_limits<int>::min();
          if (ec == std::errc::result_out_of_range || (ec == std::errc() && !fits)) {
            return fmt::format("{}: face index {} is out of range", where(), part);
          }
        }
        from = slash + 1;
      }
    }
  }
  return std::nullopt;
}

std::variant<Mesh, std::string> loadObjText(const std::filesystem::path& path, const std::string& text) {
  if (auto problem = objNumberProblem(path, text)) return *problem;
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // No material library is read (empty MTL text): a material comes from the document.
  if (!reader.ParseFromString(text, "", config)) {
    std::string why = reader.Error();
    while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back()))) why.pop_back();
    return fmt::format("{}: {}", path.string(), why.empty() ? std::string("not an OBJ file") : why);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3, uvs = attrib.texcoords.size() / 2;
  Mesh mesh;
  // One vertex per distinct (position, texture coordinate, normal) triple.
  std::map<std::tuple<int, int, int>, uint32_t> vertexOf;
  std::vector<int> positionOf;  // per vertex, for smooth normals
  bool missingNormals = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    MeshPart part;
    part.name = shape.name.empty() ? fmt::format("shape{}", mesh.parts.size()) : shape.name;
    part.firstIndex = static_cast<uint32_t>(mesh.indices.size());
    size_t corner = 0;
    for (unsigned char faceSize : shape.mesh.num_face_vertices) {
      if (faceSize != 3) return fmt::format("{}: shape '{}' has a face of {} corners after triangulation", path.string(), shape.name, int(faceSize));
      for (int k = 0; k < 3; ++k, ++corner) {
        if (corner >= shape.mesh.indices.size()) return fmt::format("{}: shape '{}' has fewer indices than corners", path.string(), shape.name);
        const tinyobj::index_t& ix = shape.mesh.indices[corner];
        if (ix.vertex_index < 0 || size_t(ix.vertex_index) >= positions || ix.normal_index >= int(normals) ||
            ix.texcoord_index >= int(uvs) || ix.normal_index < -1 || ix.texcoord_index < -1) {
          return fmt::format("{}: shape '{}': face index out of range (corner {})", path.string(), shape.name, corner);
        }
        const auto key = std::make_tuple(ix.vertex_index, ix.texcoord_index, ix.normal_index);
        auto [found, inserted] = vertexOf.emplace(key, static_cast<uint32_t>(mesh.vertices.size()));
        if (inserted) {
          Vertex v{};
          const size_t p = size_t(ix.vertex_index);
          v.position = {attrib.vertices[3 * p], attrib.vertices[3 * p + 1], attrib.vertices[3 * p + 2]};
          if (ix.normal_index >= 0) {
            const size_t n = size_t(ix.normal_index);
            v.normal = unitOr({attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]}, glm::vec3(0.0f));
          }
          if (ix.texcoord_index >= 0) {
            const size_t t = size_t(ix.texcoord_index);
            v.uv = {attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]};  // OBJ's v runs up, as ours
          }
          missingNormals = missingNormals || v.normal == glm::vec3(0.0f);
          mesh.vertices.push_back(v);
          positionOf.push_back(ix.vertex_index);
        }
        mesh.indices.push_back(found->second);
      }
    }
    part.indexCount = static_cast<uint32_t>(mesh.indices.size()) - part.firstIndex;
    if (part.indexCount > 0) mesh.parts.push_back(std::move(part));
  }
  if (mesh.indices.empty()) return fmt::format("{}: the mesh has no faces (f lines)", path.string());
  if (missingNormals) {
    // Smooth normals: the faces around each position, weighted by their area (the length of
    // the cross product is twice the area).
    std::vector<glm::vec3> sums(positions, glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const Vertex* v[3] = {&mesh.vertices[mesh.indices[i]], &mesh.vertices[mesh.indices[i + 1]], &mesh.vertices[mesh.indices[i + 2]]};
      const glm::vec3 n = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
      for (int k = 0; k < 3; ++k) sums[size_t(positionOf[mesh.indices[i + size_t(k)]])] += n;
    }
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (mesh.vertices[v].normal == glm::vec3(0.0f)) mesh.vertices[v].normal = unitOr(sums[size_t(positionOf[v])], glm::vec3(0, 1, 0));
    }
  }
  generateTangents(mesh);
  return mesh;
}

/// Why the extension of `path` names no mesh format mxc reads, if it does not.
std::optional<std::string> formatProblem(const std::filesystem::path& path) {
  const std::string extension = lower(path.extension().string());
  if (extension == ".obj" || extension == ".glb" || extension == ".gltf") return std::nullopt;
  return fmt::format("{}: unknown mesh format '{}' (expected .glb, .gltf or .obj)", path.string(), path.extension().string());
}

}  // namespace

std::variant<Mesh, std::string> loadMesh(const std::filesystem::path& path) {
  // What the path is comes first (a FIFO, a directory, nothing): then its format.
  if (auto why = inputFileProblem(path)) return fmt::format("cannot read the mesh '{}': {}", path.string(), *why);
  if (auto problem = formatProblem(path)) return *problem;
  auto bytes = readInputFile(path, kMaxMeshBytes);
  if (auto* why = std::get_if<1>(&bytes)) return fmt::format("cannot read the mesh '{}': {}", path.string(), *why);
  return loadMeshBytes(path, std::get<0>(bytes));
}

std::variant<Mesh, std::string> loadMeshBytes(const std::filesystem::path& path, const std::string& bytes) {
  if (auto problem = formatProblem(path)) return *problem;
  const std::string extension = lower(path.extension().string());
  auto mesh = extension == ".obj" ? loadObjText(path, bytes) : loadGltf(path, bytes, extension == ".glb");
  if (auto* loaded = std::get_if<Mesh>(&mesh)) {
    if (auto problem = valueProblem(*loaded)) return fmt::format("{}: {}", path.string(), *problem);
  }
  return mesh;
}

}  // namespace mxc::rt
