// The committed albedo table file's format (compiler/glsl/AlbedoTableFile.h).

#include "compiler/glsl/AlbedoTableFile.h"

#include <gtest/gtest.h>

#include "compiler/glsl/Bindings.h"

namespace mxc::glsl {
namespace {

TEST(AlbedoTableFile, RoundTrips) {
  AlbedoTableData data{2, 3, 0x0123456789abcdefull, {}};
  for (int k = 0; k < 2 * 3 * 4; ++k) data.texels.push_back(0.25f * float(k) - 1.0f);
  std::string error;
  std::optional<AlbedoTableData> back = decodeAlbedoTables(encodeAlbedoTables(data), error);
  ASSERT_TRUE(back.has_value()) << error;
  EXPECT_EQ(back->width, 2u);
  EXPECT_EQ(back->height, 3u);
  EXPECT_EQ(back->shaderHash, data.shaderHash);
  EXPECT_EQ(back->texels, data.texels);
}

TEST(AlbedoTableFile, EncodingChecksTheShape) {
  EXPECT_THROW(encodeAlbedoTables(AlbedoTableData{2, 2, 1, std::vector<float>(15, 0.5f)}), std::logic_error);
}

TEST(AlbedoTableFile, RefusesWhatIsNotATable) {
  AlbedoTableData data{2, 2, 1, std::vector<float>(16, 0.5f)};
  const std::string good = encodeAlbedoTables(data);
  std::string error;
  EXPECT_FALSE(decodeAlbedoTables("", error).has_value());
  EXPECT_NE(error.find("MXCTAB01"), std::string::npos);
  EXPECT_FALSE(decodeAlbedoTables("MXCTAB02" + good.substr(8), error).has_value());
  EXPECT_FALSE(decodeAlbedoTables(good.substr(0, good.size() - 1), error).has_value());  // truncated
  EXPECT_NE(error.find("bytes of texels"), std::string::npos);
  EXPECT_FALSE(decodeAlbedoTables(good + "x", error).has_value());  // trailing bytes
  std::string huge = good;
  huge[8] = '\xff';
  huge[9] = '\xff';  // width 65535: beyond any table
  EXPECT_FALSE(decodeAlbedoTables(huge, error).has_value());
  EXPECT_NE(error.find("shape"), std::string::npos);
}

// The committed tables have the contract's shape and were computed by the tables shader as it
// is now: a change to the library code they integrate needs scripts/generate-tables.
TEST(AlbedoTableFile, CommittedTablesAreCurrent) {
  const AlbedoTableData& tables = committedAlbedoTables();
  EXPECT_EQ(tables.width, kTableSize);
  EXPECT_EQ(tables.height, kTableHeight);
  EXPECT_EQ(committedComputedTables().height, kComputedTableHeight);
  EXPECT_EQ(committedComputedTables().shaderHash, tablesShaderHash())
      << "the tables shader changed since generated/tables was written: run scripts/generate-tables";
  // The fits the fast tier includes are there, with every array it reads.
  const std::string_view fits = committedTableFile(kAlbedoFitsPath);
  for (const char* name : {"MXC_FIT_A_P[15]", "MXC_FIT_A_Q[14]", "MXC_FIT_B_P[15]", "MXC_FIT_B_Q[14]",
                           "MXC_FIT_SHEEN_P[15]", "MXC_FIT_SHEEN_Q[14]"}) {
    EXPECT_NE(fits.find(name), std::string_view::npos) << name;
  }
}

}  // namespace
}  // namespace mxc::glsl
