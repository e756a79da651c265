// Typed values: parsing every MaterialX type, canonical spelling, and error offsets.

#include "compiler/document/Value.h"

#include <gtest/gtest.h>

namespace mxc::doc {
namespace {

Value parse(ValueType type, std::string_view text) {
  ValueError error;
  auto v = tryParseValue(type, text, &error);
  EXPECT_TRUE(v.has_value()) << text << ": " << error.message;
  return v.value_or(Value());
}

ValueError parseError(ValueType type, std::string_view text) {
  ValueError error;
  EXPECT_FALSE(tryParseValue(type, text, &error).has_value()) << text;
  return error;
}

TEST(Value, Scalars) {
  EXPECT_EQ(parse(ValueType::Boolean, "true").as<bool>(), true);
  EXPECT_EQ(parse(ValueType::Boolean, " false ").as<bool>(), false);
  EXPECT_EQ(parse(ValueType::Integer, "-42").as<int32_t>(), -42);
  EXPECT_EQ(parse(ValueType::Integer, "+7").as<int32_t>(), 7);
  EXPECT_FLOAT_EQ(parse(ValueType::Float, "0.5").as<float>(), 0.5f);
  EXPECT_FLOAT_EQ(parse(ValueType::Float, " 1e-3 ").as<float>(), 1e-3f);
  EXPECT_FLOAT_EQ(parse(ValueType::Float, ".25").as<float>(), 0.25f);
  EXPECT_FLOAT_EQ(parse(ValueType::Float, "+2.").as<float>(), 2.0f);
}

TEST(Value, VectorsColorsAndMatrices) {
  EXPECT_EQ(parse(ValueType::Color3, "0.8, 0.8,0.8").as<glm::vec3>(), glm::vec3(0.8f));
  EXPECT_EQ(parse(ValueType::Vector2, "1,2").as<glm::vec2>(), glm::vec2(1, 2));
  EXPECT_EQ(parse(ValueType::Color4, "1, 0, 0, 1").as<glm::vec4>(), glm::vec4(1, 0, 0, 1));
  // Documents write matrices row by row: row 0 is (1, 2, 3).
  glm::mat3 m = parse(ValueType::Matrix33, "1, 2, 3,  4, 5, 6,  7, 8, 9").as<glm::mat3>();
  EXPECT_EQ(m[1][0], 2.0f);  // row 0, column 1
  EXPECT_EQ(m[0][1], 4.0f);  // row 1, column 0
  Value m4 = parse(ValueType::Matrix44, "1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1");
  EXPECT_EQ(m4.as<glm::mat4>()[0][3], 5.0f);
  EXPECT_EQ(m4.components().size(), 16u);
  EXPECT_EQ(m4.str(), "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1");
}

TEST(Value, Arrays) {
  EXPECT_EQ(parse(ValueType::IntegerArray, "1, 2, 3").as<std::vector<int32_t>>(), (std::vector<int32_t>{1, 2, 3}));
  EXPECT_TRUE(parse(ValueType::FloatArray, "").as<std::vector<float>>().empty());
  EXPECT_EQ(parse(ValueType::Vector2Array, "0,1, 2,3").as<std::vector<glm::vec2>>().size(), 2u);
  EXPECT_EQ(parse(ValueType::Color3Array, "1,0,0, 0,1,0").str(), "1, 0, 0, 0, 1, 0");
  EXPECT_EQ(parse(ValueType::StringArray, "a, b ,c").as<std::vector<std::string>>(),
            (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_NE(parseError(ValueType::Vector3Array, "1,2,3,4").message.find("multiple of 3"), std::string::npos);
}

// MaterialX separates a numeric value's components by commas, white space or both, and skips
// empty pieces (its separators are ", "); documents of its test suite write "0.944 0.776 0.373"
// and "1 1,1".
TEST(Value, NumbersAreSeparatedByCommasOrWhiteSpace) {
  EXPECT_EQ(parse(ValueType::Color3, "0.944 0.776 0.373").as<glm::vec3>(), glm::vec3(0.944f, 0.776f, 0.373f));
  EXPECT_EQ(parse(ValueType::Vector3, "1 1,1").as<glm::vec3>(), glm::vec3(1.0f));
  EXPECT_EQ(parse(ValueType::Vector2, "1,,2").as<glm::vec2>(), glm::vec2(1.0f, 2.0f));
  EXPECT_EQ(parse(ValueType::Vector2, "\t3,\n 4 ").as<glm::vec2>(), glm::vec2(3.0f, 4.0f));
  EXPECT_EQ(parse(ValueType::IntegerArray, "1 2, 3").as<std::vector<int32_t>>(), (std::vector<int32_t>{1, 2, 3}));
  EXPECT_EQ(parse(ValueType::FloatArray, " ").as<std::vector<float>>().size(), 0u);
}

TEST(Value, StringsAreKeptAsWritten) {
  EXPECT_EQ(parse(ValueType::String, " spaced, text ").as<std::string>(), " spaced, text ");
  EXPECT_EQ(parse(ValueType::Filename, "a/b c.png").as<std::string>(), "a/b c.png");
}

TEST(Value, CanonicalSpellingRoundTrips) {
  for (std::string_view text : {"0.8, 0.8, 0.8", "0.1, 1e-05, 123456", "-0, 3.5, 0.333"}) {
    Value v = parse(ValueType::Color3, text);
    EXPECT_EQ(parse(ValueType::Color3, v.str()), v);
  }
  EXPECT_EQ(formatFloat(0.1f), "0.1");
  EXPECT_EQ(formatFloat(1.0f), "1");
}

TEST(Value, ErrorsPointAtTheBadComponent) {
  ValueError e = parseError(ValueType::Color3, "1, x, 3");
  EXPECT_EQ(e.offset, 3u);
  EXPECT_NE(e.message.find("'x' is not a number"), std::string::npos);
  e = parseError(ValueType::Vector3, "1 2 x");
  EXPECT_EQ(e.offset, 4u);
  EXPECT_NE(e.message.find("'x' is not a number"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Vector2, "1,,2,3").message.find("needs 2 numbers, found 3"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Float, " ").message.find("needs 1 number, found 0"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Float, "nan").message.find("finite"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Float, "f1").message.find("not a number"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Integer, "x1").message.find("not an integer"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Integer, "1, 2").message.find("needs 1 number"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Boolean, "1").message.find("true or false"), std::string::npos);
  EXPECT_NE(parseError(ValueType::None, "x").message.find("no literal values"), std::string::npos);
}

// MaterialX reads a number as a C++ stream does, its longest prefix that is a number (its own
// test suite writes "0.5.0" in a matrix44, vector_math.mtlx); mxc reads the same value and says
// where it read past something, pointing after the number.
TEST(Value, NumbersAreReadAsMaterialXReadsThem) {
  auto lenient = [](ValueType type, std::string_view text, ValueError& ignored) {
    ValueError error;
    std::optional<Value> v = tryParseValue(type, text, &error, &ignored);
    EXPECT_TRUE(v.has_value()) << text << ": " << error.message;
    return v.value_or(Value());
  };
  ValueError ignored;
  EXPECT_EQ(lenient(ValueType::Vector3, "1, 0.5.0, 3", ignored).as<glm::vec3>(), glm::vec3(1.0f, 0.5f, 3.0f));
  EXPECT_EQ(ignored.offset, 6u);
  EXPECT_NE(ignored.message.find("'0.5.0' is read as 0.5, as MaterialX reads it: '.0' after the number is ignored"),
            std::string::npos)
      << ignored.message;
  ignored = {};
  EXPECT_FLOAT_EQ(lenient(ValueType::Float, "+1.0f", ignored).as<float>(), 1.0f);
  EXPECT_EQ(ignored.offset, 4u);  // after "+1.0"
  ignored = {};
  EXPECT_EQ(lenient(ValueType::Integer, "2.5", ignored).as<int32_t>(), 2);
  EXPECT_NE(ignored.message.find("'2.5' is read as 2"), std::string::npos) << ignored.message;
  ignored = {};
  EXPECT_EQ(lenient(ValueType::IntegerArray, "1, 2e3", ignored).as<std::vector<int32_t>>(), (std::vector<int32_t>{1, 2}));
  EXPECT_EQ(ignored.offset, 4u);
  // Only the first place is reported; a value read exactly leaves `ignored` empty.
  ignored = {};
  lenient(ValueType::Vector2, "1x, 2y", ignored);
  EXPECT_EQ(ignored.offset, 1u);
  ignored = {};
  lenient(ValueType::Color3, "0.1, 0.2, 0.3", ignored);
  EXPECT_TRUE(ignored.message.empty());
  // What a stream cannot read stays an error: no number at the start, out of range, not finite.
  EXPECT_NE(parseError(ValueType::Float, ".").message.find("not a number"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Float, "1e40x").message.find("out of the range"), std::string::npos);
  EXPECT_NE(parseError(ValueType::Float, "infinity").message.find("finite"), std::string::npos);
}

TEST(Value, TypeNames) {
  EXPECT_EQ(valueTypeOf("color3"), ValueType::Color3);
  EXPECT_EQ(valueTypeOf("BSDF"), ValueType::None);
  EXPECT_EQ(typeName(ValueType::Matrix44), "matrix44");
  EXPECT_TRUE(isStandardTypeName("surfaceshader"));
  EXPECT_TRUE(isStandardTypeName("multioutput"));
  EXPECT_FALSE(isStandardTypeName("colour3"));
  EXPECT_EQ(componentCount(ValueType::Matrix33), 9);
}

}  // namespace
}  // namespace mxc::doc
