// SourceTrim (compiler/spirv/SourceTrim.h): comments, branches not taken and functions nothing
// calls leave the text glslang parses, every line stays on its line, text the trim cannot follow
// is left as it is, and for every shader library of the corpus glslang writes the same module
// from the trimmed text as from the whole.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "compiler/spirv/SourceTrim.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "support/ShaderSupport.h"

namespace mxc::test {
namespace {

using spirv::trimForParse;

size_t lineCount(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

/// The 1-based line of `token` in `text`, 0 when absent.
size_t lineOf(const std::string& text, const std::string& token) {
  const size_t at = text.find(token);
  return at == std::string::npos ? 0 : lineCount(text.substr(0, at)) + 1;
}

TEST(SourceTrim, CommentsAndIndentationGoAndEveryLineKeepsItsNumber) {
  const std::string glsl =
      "#version 450\n"
      "// a line comment\n"
      "float f(float x) { /* a block\n"
      "   comment over lines */ return x * 2.0; }  // trailing\n"
      "    void main() { float y = f(1.0); }\n";
  const auto trimmed = trimForParse(glsl);
  ASSERT_TRUE(trimmed.trimmed);
  EXPECT_EQ(trimmed.text.find("comment"), std::string::npos) << trimmed.text;
  EXPECT_EQ(trimmed.text.find("trailing"), std::string::npos);
  EXPECT_EQ(lineCount(trimmed.text), lineCount(glsl));
  EXPECT_EQ(lineOf(trimmed.text, "return x"), lineOf(glsl, "return x"));
  EXPECT_EQ(lineOf(trimmed.text, "void main"), 5u);
  EXPECT_EQ(trimmed.text.find("    void"), std::string::npos) << "indentation is removed";
}

TEST(SourceTrim, ConditionalsAreEvaluatedAndTheBranchesNotTakenRemoved) {
  const std::string glsl =
      "#version 450\n"
      "#define MXC_A\n"
      "#ifdef MXC_A\nint a_taken;\n#else\nint a_not;\n#endif\n"
      "#ifndef MXC_B\nint b_taken;\n#endif\n"
      "#if defined(MXC_A) && !defined(MXC_B)\nint and_taken;\n#endif\n"
      "#if defined(MXC_B) || (defined MXC_A && 1)\nint or_taken;\n#endif\n"
      "#if defined(MXC_B)\nint elif_not;\n#elif defined(MXC_A)\nint elif_taken;\n#else\nint else_not;\n#endif\n"
      "#ifdef MXC_B\n#ifdef MXC_A\nint nested_not;\n#endif\n#else\nint nested_taken;\n#endif\n"
      "#undef MXC_A\n#ifdef MXC_A\nint undef_not;\n#endif\n"
      "void main() {}\n";
  const auto trimmed = trimForParse(glsl);
  ASSERT_TRUE(trimmed.trimmed);
  for (const char* taken : {"a_taken", "b_taken", "and_taken", "or_taken", "elif_taken", "nested_taken"}) {
    EXPECT_NE(trimmed.text.find(taken), std::string::npos) << taken << "\n" << trimmed.text;
    EXPECT_EQ(lineOf(trimmed.text, taken), lineOf(glsl, taken)) << taken;
  }
  for (const char* removed : {"a_not", "elif_not", "else_not", "nested_not", "undef_not", "#if", "#else", "#endif"}) {
    EXPECT_EQ(trimmed.text.find(removed), std::string::npos) << removed << "\n" << trimmed.text;
  }
  EXPECT_NE(trimmed.text.find("#define MXC_A"), std::string::npos) << "glslang still expands the macros";
  EXPECT_EQ(lineCount(trimmed.text), lineCount(glsl));
}

TEST(SourceTrim, WhatItCannotFollowIsLeftUnchanged) {
  for (const std::string& glsl : {
           std::string("#version 450\n#if MXC_COUNT > 2\nint x;\n#endif\nvoid main() {}\n"),  // a comparison
           std::string("#version 450\n#ifdef GL_ES\nint x;\n#endif\nvoid main() {}\n"),  // glslang's own macro
           std::string("#version 450\n#ifdef MXC_A\nint x;\nvoid main() {}\n"),              // no #endif
           std::string("#version 450\n#endif\nvoid main() {}\n"),                            // an #endif alone
           std::string("#version 450\n/* never closed\nvoid main() {}\n"),                   // a comment
           std::string("#version 450\nvoid main() { }}\n"),                                   // a brace
       }) {
    const auto trimmed = trimForParse(glsl);
    EXPECT_FALSE(trimmed.trimmed) << glsl;
    EXPECT_EQ(trimmed.text, glsl);
  }
}

TEST(SourceTrim, OnlyFunctionsNothingCanCallAreRemoved) {
  const std::string glsl =
      "#version 450\n"
      "#define MXC_TWICE(X) macro_only(X)\n"
      "float macro_only(float x) { return x; }\n"
      "float overloaded(float x) { return x; }\n"
      "vec2 overloaded(vec2 x) { return x; }\n"
      "float initialiser() { return 1.0; }\n"
      "float gValue = initialiser();\n"
      "float callee() { return 2.0; }\n"
      "float caller() { return callee(); }\n"
      "float unused_leaf() { return 3.0; }\n"
      "float unused_root() { return unused_leaf() + callee(); }\n"
      "struct S { float v; };\n"
      "float pinned() {\n#define MXC_INSIDE 1\nreturn 4.0; }\n"
      "#define MXC_DEFINE(NAME) float NAME() { return 5.0; }\n"
      "MXC_DEFINE(from_macro)\n"
      "float after_macro() { return 6.0; }\n"
      "layout(location = 0) out vec4 colour;\n"
      "void main() { colour = vec4(caller() + overloaded(1.0) + MXC_TWICE(gValue) + from_macro()); }\n";
  const auto trimmed = trimForParse(glsl);
  ASSERT_TRUE(trimmed.trimmed);
  for (const char* kept : {"float macro_only", "float overloaded", "vec2 overloaded", "float initialiser",
                           "float callee", "float caller", "struct S", "float pinned", "void main",
                           // a macro invoked without a `;`: its text and the function after it stay
                           "MXC_DEFINE(from_macro)", "float after_macro"}) {
    EXPECT_NE(trimmed.text.find(kept), std::string::npos) << kept << "\n" << trimmed.text;
  }
  EXPECT_EQ(trimmed.text.find("unused_leaf"), std::string::npos) << trimmed.text;
  EXPECT_EQ(trimmed.text.find("unused_root"), std::string::npos);
  EXPECT_EQ(trimmed.functionsRemoved, 2u);
  EXPECT_EQ(lineCount(trimmed.text), lineCount(glsl));

  // The module is the one glslang writes from the whole text.
  spirv::GlslSource source;
  source.text = glsl;
  source.name = "trim";
  Diagnostics diagnostics;
  spirv::CompileOptions whole;
  whole.trimSource = false;
  const auto a = spirv::compile(source, {}, diagnostics);
  const auto b = spirv::compile(source, whole, diagnostics);
  ASSERT_TRUE(a && b) << diagnostics.format();
  EXPECT_EQ(*a, *b);
}

TEST(SourceTrim, AnErrorNamesTheLineOfTheWholeText) {
  spirv::GlslSource source;
  source.name = "broken";
  source.text = "#version 450\n/* a comment\n   of three lines */\nvoid main() {\n  undeclared_name = 1.0;\n}\n";
  Diagnostics diagnostics;
  EXPECT_FALSE(spirv::compile(source, {}, diagnostics));
  EXPECT_NE(diagnostics.format().find("generated line 5"), std::string::npos) << diagnostics.format();
}

TEST(SourceTrim, EveryCorpusLibraryCompilesToTheSameModuleTrimmedOrNot) {
  Context context;
  std::map<std::string, spirv::GlslSource> libraries;  // one shader per library
  for (KeyedShader& s : corpusShaders(context)) libraries.emplace(s.libraryKey, std::move(s.glsl));
  ASSERT_GE(libraries.size(), 30u) << context.diagnostics.format();
  spirv::CompileOptions whole;
  whole.trimSource = false;
  for (const auto& [key, source] : libraries) {
    const auto trimmed = trimForParse(source.text);
    EXPECT_TRUE(trimmed.trimmed) << source.name << ": the library's text is one the trim follows";
    EXPECT_LT(trimmed.text.size(), source.text.size() * 2 / 3) << source.name;
    EXPECT_EQ(lineCount(trimmed.text), lineCount(source.text)) << source.name;
    Diagnostics diagnostics;
    const auto a = spirv::compile(source, {}, diagnostics);
    const auto b = spirv::compile(source, whole, diagnostics);
    ASSERT_TRUE(a && b) << source.name << ": " << diagnostics.format();
    EXPECT_EQ(*a, *b) << source.name << ": trimming changed the module";
  }
}

}  // namespace
}  // namespace mxc::test
