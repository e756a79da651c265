// Reading meshes: OBJ through tinyobjloader and glTF through tinygltf, in the renderer's
// conventions (v up, counter-clockwise fronts, unit normals and tangents), and every malformed
// file refused with a message naming it.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "runtime/MeshFile.h"
#include <fstream>

#include <unistd.h>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

/// `text` in a file of the temporary folder whose name ends with `name`.
fs::path writeTemp(const std::string& name, const std::string& text) {
  fs::path path = fs::temp_directory_path() / ("mxc_mesh_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

using rt::loadMesh;
using rt::Mesh;

Mesh load(const fs::path& path) {
  auto loaded = loadMesh(path);
  if (auto* why = std::get_if<std::string>(&loaded)) ADD_FAILURE() << *why;
  return std::holds_alternative<Mesh>(loaded) ? std::get<Mesh>(loaded) : Mesh{};
}

std::string loadError(const fs::path& path) {
  auto loaded = loadMesh(path);
  EXPECT_TRUE(std::holds_alternative<std::string>(loaded)) << path;
  return std::holds_alternative<std::string>(loaded) ? std::get<std::string>(loaded) : std::string();
}

/// The face normal of triangle t (counter-clockwise front).
glm::vec3 faceNormal(const Mesh& mesh, size_t t) {
  const glm::vec3 a = mesh.vertices[mesh.indices[3 * t]].position, b = mesh.vertices[mesh.indices[3 * t + 1]].position,
                  c = mesh.vertices[mesh.indices[3 * t + 2]].position;
  return glm::normalize(glm::cross(b - a, c - a));
}

/// Every frame orthonormal, w = +-1, every index in range.
void expectWellFormed(const Mesh& mesh) {
  for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());
  for (const rt::Vertex& v : mesh.vertices) {
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
    ASSERT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-3f);
    ASSERT_EQ(std::abs(v.tangent.w), 1.0f);
  }
}

TEST(ObjMesh, ReadsPositionsTextureCoordinatesAndNormals) {
  // A unit quad in the xy plane facing +z, u along +x, v along +y.
  const fs::path path = writeTemp("quad.obj",
                                  "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                  "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
  const Mesh mesh = load(path);
  ASSERT_EQ(mesh.indices.size(), 6u);  // the quad as a fan of two triangles
  ASSERT_EQ(mesh.vertices.size(), 4u);
  expectWellFormed(mesh);
  for (const rt::Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.uv, glm::vec2(v.position.x, v.position.y));  // OBJ's v runs up, as ours
    EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);  // along increasing u
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
  EXPECT_GT(faceNormal(mesh, 0).z, 0.99f);
}

TEST(ObjMesh, ComputesSmoothNormalsWhereTheFileHasNone) {
  // Two faces folded along the x axis at 90 degrees: +y and +z facing. The shared edge's
  // normal is their area-weighted mean, (0, 1, 1) / sqrt 2 for equal areas.
  const fs::path path = writeTemp("fold.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nv 1 1 0\nv 0 1 0\n"
                                              "f 1 2 3 4\nf 1 2 5 6\n");
  const Mesh mesh = load(path);
  ASSERT_EQ(mesh.indices.size(), 12u);
  expectWellFormed(mesh);
  for (const rt::Vertex& v : mesh.vertices) {
    if (v.position.z == 0.0f && v.position.y == 0.0f) {  // on the fold
      EXPECT_NEAR(v.normal.y, std::sqrt(0.5f), 1e-5f);
      EXPECT_NEAR(v.normal.z, std::sqrt(0.5f), 1e-5f);
    } else {
      EXPECT_NEAR(std::abs(v.normal.y) + std::abs(v.normal.z), 1.0f, 1e-5f);
    }
  }
  // The fronts face where the normals point.
  for (size_t t = 0; t < 4; ++t) {
    const glm::vec3 n = faceNormal(mesh, t);
    for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(n, mesh.vertices[mesh.indices[3 * t + k]].normal), 0.5f);
  }
}

TEST(ObjMesh, RefusesMalformedFilesNamingThem) {
  const fs::path outOfRange = writeTemp("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  EXPECT_NE(loadError(outOfRange).find("range.obj"), std::string::npos);
  const fs::path noFaces = writeTemp("nofaces.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_NE(loadError(noFaces).find("no faces"), std::string::npos);
  const fs::path nan = writeTemp("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n");
  const std::string why = loadError(nan);
  EXPECT_NE(why.find("nan.obj"), std::string::npos) << why;
  // tinyobjloader reads nan and inf as 0, and wraps an index beyond an int to -1 (the last
  // vertex): refused at their line and column.
  for (const char* value : {"nan", "inf", "-inf", "1e400", "NaN"}) {
    const fs::path bad = writeTemp("bad_value.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 ") + value + " 0\nf 1 2 3\n");
    const std::string message = loadError(bad);
    EXPECT_NE(message.find("bad_value.obj:3:5: '" + std::string(value) + "' is not a finite number"), std::string::npos)
        << message;
  }
  // A finite triangle 1e10 across: its normal overflowed and it was "NaN or infinite values".
  const fs::path huge = writeTemp("huge.obj", "v 0 0 0\nv 1e10 0 0\nv 0 1e10 0\nf 1 2 3\n");
  EXPECT_NE(loadError(huge).find("huge.obj: the mesh reaches 1e+10 units from the origin, and mxc renders meshes within 1e+09"),
            std::string::npos)
      << loadError(huge);
  EXPECT_TRUE(std::holds_alternative<Mesh>(loadMesh(writeTemp("large.obj", "v 0 0 0\nv 1e9 0 0\nv 0 1e9 0\nf 1 2 3\n"))));
  const fs::path wraps = writeTemp("wraps.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n");
  EXPECT_NE(loadError(wraps).find("wraps.obj:4:7: face index 99999999999999999999 is out of range"), std::string::npos)
      << loadError(wraps);
  const fs::path wrapsSlash = writeTemp("wraps2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/4294967297\n");
  EXPECT_NE(loadError(wrapsSlash).find("face index 4294967297 is out of range"), std::string::npos) << loadError(wrapsSlash);
  const fs::path absent = writeTemp("absent.obj", "");
  fs::remove(absent);
  EXPECT_NE(loadError(absent).find("absent.obj"), std::string::npos);
  EXPECT_NE(loadError(writeTemp("mesh.ply", "ply\n")).find("unknown mesh format"), std::string::npos);
  // A device behind an .obj name: refused before a byte is read, not read forever.
  const fs::path device = writeTemp("zero.obj", "");
  fs::remove(device);
  fs::create_symlink("/dev/zero", device);
  EXPECT_NE(loadError(device).find("zero.obj"), std::string::npos);
  fs::remove(device);
}

/// Base64 of bytes (RFC 4648), for a glTF data URI.
std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 2]));
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

template <typename T>
void append(std::string& bytes, std::initializer_list<T> values) {
  for (T v : values) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
}

/// A .gltf of one triangle (0,0,0), (1,0,0), (0,1,0) facing +z, uv (0,0), (1,0), (0,1) in
/// glTF's convention, with `indexCount` unsigned-short indices (3; more reach past the buffer),
/// under a node with `node` (JSON members).
fs::path triangleGltf(const std::string& name, const std::string& node, int indexCount = 3) {
  std::string data;
  append<float>(data, {0, 0, 0, 1, 0, 0, 0, 1, 0});  // positions: 36 bytes
  append<float>(data, {0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals: 36 bytes
  append<float>(data, {0, 0, 1, 0, 0, 1});  // texture coordinates: 24 bytes
  append<uint16_t>(data, {0, 1, 2, 0});  // indices: 6 bytes and padding
  const size_t length = data.size();
  const std::string json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0)" + node + R"(}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
    "buffers": [{"byteLength": )" + std::to_string(length) + R"(, "uri": "data:application/octet-stream;base64,)" +
                           base64(data) + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                    {"buffer": 0, "byteOffset": 72, "byteLength": 24}, {"buffer": 0, "byteOffset": 96, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                  {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
                  {"bufferView": 3, "componentType": 5123, "count": )" +
                           std::to_string(indexCount) + R"(, "type": "SCALAR"}]})";
  return writeTemp(name, json);
}

TEST(GltfMesh, ABufferThatIsNotARegularFileIsNamedForWhatItIs) {
  // tinygltf said "File not found" for a FIFO, a folder and /dev/zero (an absolute URI was
  // looked up under the file's folder).
  const fs::path folder = fs::temp_directory_path() / ("mxc_gltf_buffers_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder / "adir");
  ASSERT_EQ(::mkfifo((folder / "fifo").c_str(), 0600), 0);
  for (const auto& [uri, what] : std::vector<std::pair<std::string, std::string>>{
           {"fifo", "it is a FIFO (named pipe), not a regular file"},
           {"adir", "it is a directory, not a file"},
           {"/dev/zero", "cannot read '/dev/zero': it is a character device, not a regular file"},
           {"missing.bin", "File not found : missing.bin"}}) {
    const fs::path file = folder / "m.gltf";
    std::ofstream(file) << R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" << uri
                        << R"(","byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
                        << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
                        << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    const std::string error = loadError(file);
    EXPECT_NE(error.find(what), std::string::npos) << uri << ": " << error;
  }
  fs::remove_all(folder);
}

TEST(GltfMesh, ReadsAPrimitiveUnderItsNodeTransform) {
  const Mesh mesh = load(triangleGltf("moved.gltf", R"(, "translation": [1, 2, 3], "scale": [2, 2, 2])"));
  ASSERT_EQ(mesh.indices.size(), 3u);
  expectWellFormed(mesh);
  EXPECT_EQ(mesh.vertices[mesh.indices[0]].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(mesh.vertices[mesh.indices[1]].position, glm::vec3(3, 2, 3));
  // glTF's v runs down the image: (0, 1) there is (0, 0) here.
  EXPECT_EQ(mesh.vertices[mesh.indices[2]].uv, glm::vec2(0, 0));
  EXPECT_EQ(mesh.vertices[mesh.indices[0]].uv, glm::vec2(0, 1));
  EXPECT_GT(faceNormal(mesh, 0).z, 0.99f);
  // The tangent follows increasing u (+x); v now decreases along +y, so the bitangent
  // w * cross(n, t) = w * (+y) must point down: w = -1.
  for (const rt::Vertex& v : mesh.vertices) {
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(GltfMesh, AMirroringTransformKeepsTheFrontFacingOut) {
  // A scale of -1 in x mirrors the triangle; glTF then reverses the winding (spec 3.7.1), so the
  // face still faces where its (transformed) normal points.
  const Mesh mesh = load(triangleGltf("mirrored.gltf", R"(, "scale": [-1, 1, 1])"));
  ASSERT_EQ(mesh.indices.size(), 3u);
  expectWellFormed(mesh);
  EXPECT_GT(glm::dot(faceNormal(mesh, 0), mesh.vertices[0].normal), 0.99f);
  EXPECT_GT(faceNormal(mesh, 0).z, 0.99f);
}

TEST(GltfMesh, RefusesMalformedFilesNamingThem) {
  // An index accessor longer than its buffer view.
  std::string why = loadError(triangleGltf("short.gltf", "", 300));
  EXPECT_NE(why.find("short.gltf"), std::string::npos) << why;
  // A node that is its own child: a cycle.
  why = loadError(triangleGltf("cycle.gltf", R"(, "children": [0])"));
  EXPECT_NE(why.find("cycle.gltf"), std::string::npos) << why;
  // A POSITION accessor of 2^31 elements and no buffer view: refused before any allocation.
  const std::string huge = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"componentType": 5126, "count": 2147483648, "type": "VEC3"}]})";
  why = loadError(writeTemp("huge.gltf", huge));
  EXPECT_NE(why.find("has no buffer view"), std::string::npos) << why;
  // Not JSON at all.
  why = loadError(writeTemp("garbage.gltf", "{ nope"));
  EXPECT_NE(why.find("garbage.gltf"), std::string::npos) << why;
  why = loadError(writeTemp("garbage.glb", "glTF\x02"));
  EXPECT_NE(why.find("garbage.glb"), std::string::npos) << why;
}

TEST(GltfMesh, ReadsTheShaderBall) {
  const fs::path path = sharedDir() / "conformance/materialx-tree/resources/Geometry/shaderball.glb";
  if (!fs::exists(path)) GTEST_SKIP() << "no " << path;
  const Mesh mesh = load(path);
  // The file's two meshes (preview and calibration), at least their 36228 + ... vertices (more
  // where MikkTSpace splits a mirror seam), every triangle of them.
  EXPECT_GE(mesh.vertices.size(), 36228u);
  EXPECT_EQ(mesh.indices.size() % 3, 0u);
  expectWellFormed(mesh);
  // The bounds the file's accessors declare for the preview mesh lie inside the mesh's.
  const rt::MeshBounds bounds = rt::meshBounds(mesh);
  EXPECT_GT(bounds.radius, 1.0f);
  EXPECT_LT(bounds.radius, 2.0f);
  // Its nodes are the parts MaterialX's looks assign (standard_surface_look_wood_tiled.mtlx),
  // in order, covering every triangle once.
  ASSERT_EQ(mesh.parts.size(), 2u);
  EXPECT_EQ(mesh.parts[0].name, "Preview_Mesh");
  EXPECT_EQ(mesh.parts[1].name, "Calibration_Mesh");
  EXPECT_EQ(mesh.parts[0].firstIndex, 0u);
  EXPECT_EQ(mesh.parts[1].firstIndex, mesh.parts[0].indexCount);
  EXPECT_EQ(mesh.parts[0].indexCount + mesh.parts[1].indexCount, mesh.indices.size());
}

TEST(ObjMesh, ObjectsAndGroupsAreParts) {
  const fs::path path = writeTemp("parts.obj", "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                                               "o second\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\nf 4 5 7 6\n");
  const Mesh mesh = load(path);
  ASSERT_EQ(mesh.parts.size(), 2u);
  EXPECT_EQ(mesh.parts[0].name, "first");
  EXPECT_EQ(mesh.parts[0].indexCount, 3u);
  EXPECT_EQ(mesh.parts[1].name, "second");
  EXPECT_EQ(mesh.parts[1].firstIndex, 3u);
  EXPECT_EQ(mesh.parts[1].indexCount, 6u);
}

}  // namespace
}  // namespace mxc::test
