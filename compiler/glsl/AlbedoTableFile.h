#pragma once
/// \file
/// The committed albedo tables and their fits: the files scripts/generate-tables writes under
/// generated/tables, embedded into the binary (cmake/EmbedFiles.cmake), read by the harness
/// (runtime/AlbedoTables: one texture) and by the shader builder (the fast tier's fits). The
/// binary format is declared here once, for the generator, the loader and the tests:
///
///   8 bytes  "MXCTAB01"
///   uint32   width (kTableSize), height (kTableHeight), channels (4)   little-endian
///   uint64   hash of the GLSL that computed them (tablesShaderHash)   little-endian
///   float32  width * height * channels texels, row by row             little-endian

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mxc::glsl {

inline constexpr std::string_view kAlbedoTablesPath = "tables/mxc_albedo_tables.bin";
inline constexpr std::string_view kAlbedoFitsPath = "tables/mxc_albedo_fits.glsl";
/// The reference walk's tables (tools/GenerateWalkFits.cpp), the image's rows under the computed ones.
inline constexpr std::string_view kWalkTablesPath = "tables/mxc_walk_tables.bin";

struct AlbedoTableData {
  uint32_t width = 0;
  uint32_t height = 0;
  uint64_t shaderHash = 0;
  std::vector<float> texels;  ///< width * height RGBA
};

std::string encodeAlbedoTables(const AlbedoTableData& data);
/// The tables in `bytes`, or nullopt with `error` saying what is wrong.
std::optional<AlbedoTableData> decodeAlbedoTables(std::string_view bytes, std::string& error);

/// The bytes of a committed table file (kAlbedoTablesPath, kAlbedoFitsPath), embedded at build.
std::string_view committedTableFile(std::string_view path);

/// The committed tables: the computed ones (kAlbedoTablesPath, kComputedTableHeight rows) with
/// the walk's under them (kWalkTablesPath, kWalkTableRows rows), the whole image the shaders
/// sample (kTableSize x kTableHeight). Throws std::runtime_error when a file does not hold them
/// (regenerate with scripts/generate-tables).
const AlbedoTableData& committedAlbedoTables();
/// The computed tables alone (kTableSize x kComputedTableHeight), as the tables shader writes them.
const AlbedoTableData& committedComputedTables();

/// FNV-1a hash of the tables shader's whole GLSL (buildTablesShader): a committed file whose
/// hash differs was computed by other code.
uint64_t tablesShaderHash();

}  // namespace mxc::glsl
