#include "compiler/glsl/AlbedoTableFile.h"

#include <bit>
#include <cstring>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/common/EmbeddedFile.h"
#include "compiler/glsl/Bindings.h"
#include "compiler/glsl/ShaderBuilder.h"

namespace mxc {
std::span<const EmbeddedFile> tableFiles();  // cmake/EmbedFiles.cmake: generated/tables
}

namespace mxc::glsl {

namespace {

constexpr std::string_view kMagic = "MXCTAB01";
constexpr size_t kHeaderBytes = 8 + 3 * 4 + 8;
constexpr uint32_t kChannels = 4;

static_assert(std::endian::native == std::endian::little, "the table file is little-endian, as this machine");

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

template <typename T>
T get(std::string_view bytes, size_t offset) {
  T value{};
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

}  // namespace

std::string encodeAlbedoTables(const AlbedoTableData& data) {
  if (data.texels.size() != size_t{data.width} * data.height * kChannels) {
    throw std::logic_error(fmt::format("{} texel values for a {} x {} table", data.texels.size(), data.width, data.height));
  }
  std::string out(kMagic);
  put(out, data.width);
  put(out, data.height);
  put(out, kChannels);
  put(out, data.shaderHash);
  out.append(reinterpret_cast<const char*>(data.texels.data()), data.texels.size() * sizeof(float));
  return out;
}

std::optional<AlbedoTableData> decodeAlbedoTables(std::string_view bytes, std::string& error) {
  if (bytes.size() < kHeaderBytes || bytes.substr(0, kMagic.size()) != kMagic) {
    error = "not an mxc albedo table file (no MXCTAB01 header)";
    return std::nullopt;
  }
  AlbedoTableData data;
  data.width = get<uint32_t>(bytes, 8);
  data.height = get<uint32_t>(bytes, 12);
  const uint32_t channels = get<uint32_t>(bytes, 16);
  data.shaderHash = get<uint64_t>(bytes, 20);
  // Both sizes are bounded before they are multiplied: no overflow.
  if (channels != kChannels || data.width == 0 || data.height == 0 || data.width > 4096 || data.height > 65536) {
    error = fmt::format("unexpected table shape {} x {} x {}", data.width, data.height, channels);
    return std::nullopt;
  }
  const size_t count = size_t{data.width} * data.height * channels;
  if (bytes.size() != kHeaderBytes + count * sizeof(float)) {
    error = fmt::format("{} bytes of texels, expected {}", bytes.size() - kHeaderBytes, count * sizeof(float));
    return std::nullopt;
  }
  data.texels.resize(count);
  std::memcpy(data.texels.data(), bytes.data() + kHeaderBytes, count * sizeof(float));
  return data;
}

std::string_view committedTableFile(std::string_view path) {
  for (const EmbeddedFile& f : tableFiles()) {
    if (f.path == path) return f.contents;
  }
  throw std::logic_error(fmt::format("table file {} is not embedded", path));  // a build error
}

namespace {

/// A committed table file of `rows` rows of kTableSize texels; throws naming what is wrong.
AlbedoTableData committedRows(std::string_view path, uint32_t rows, const char* generator) {
  std::string error;
  std::optional<AlbedoTableData> data = decodeAlbedoTables(committedTableFile(path), error);
  if (data && (data->width != kTableSize || data->height != rows)) {
    error = fmt::format("the tables are {} x {}, the shaders read {} x {}", data->width, data->height, kTableSize, rows);
    data.reset();
  }
  if (!data) throw std::runtime_error(fmt::format("generated/{}: {}; regenerate it with {}", path, error, generator));
  return std::move(*data);
}

}  // namespace

const AlbedoTableData& committedComputedTables() {
  static const AlbedoTableData tables = committedRows(kAlbedoTablesPath, kComputedTableHeight, "scripts/generate-tables");
  return tables;
}

const AlbedoTableData& committedAlbedoTables() {
  static const AlbedoTableData tables = [] {
    AlbedoTableData all = committedComputedTables();
    const AlbedoTableData walk = committedRows(kWalkTablesPath, kWalkTableRows, "scripts/generate-tables --walk");
    all.height += walk.height;
    all.texels.insert(all.texels.end(), walk.texels.begin(), walk.texels.end());
    return all;
  }();
  return tables;
}

uint64_t tablesShaderHash() {
  uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
  for (unsigned char c : buildTablesShader().text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace mxc::glsl
