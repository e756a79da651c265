// Nodes implemented by inline source code (compiler/lower/InlineSource.cpp): struct members,
// GLSL's operators and built-ins, and the messages for what mxc does not lower. The strongest
// check runs MaterialX's own genglsl inline implementations (a copy of each nodedef under a new
// name, implemented by MaterialX's source text) against mxc's rules for the original node, on
// the same constant inputs.

#include <gtest/gtest.h>

#include <cmath>

#include "compiler/driver/Compiler.h"
#include "compiler/ir/Evaluate.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

/// The emission colour of a document whose unlit surface emits node `source` (a color3), or
/// the first error's message.
struct Emitted {
  std::vector<float> color;
  std::string error;
};

Emitted emitted(const std::string& definitions, const std::string& nodes, const std::string& source) {
  Context context;
  CompileRequest request;
  request.document = "test.mtlx";
  request.text = mtlx(definitions + nodes + "  <surface_unlit name=\"surf\" type=\"surfaceshader\">\n"
                      "    <input name=\"emission_color\" type=\"color3\" nodename=\"" + source + "\"/>\n"
                      "  </surface_unlit>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                      "type=\"surfaceshader\" nodename=\"surf\"/></surfacematerial>\n");
  Compiler compiler(context, std::move(request));
  std::vector<ir::Material> materials = std::move(compiler.materials());
  Emitted result;
  if (context.diagnostics.hasErrors()) {
    result.error = context.diagnostics.format();
    return result;
  }
  if (materials.empty()) return result;
  const ir::Material& m = materials[0];
  if (m.emissions.empty()) {
    result.color = {0.0f, 0.0f, 0.0f};  // a black emission is removed by the passes
    return result;
  }
  std::optional<ir::Constant> c = ir::evaluateExpr(m.exprs, m.emissions[0].slots.value(ir::Slot::Color));
  if (c) result.color = c->v;
  return result;
}

const std::string kTexcoordStruct =
    "  <typedef name=\"texcoord_struct\">\n"
    "    <member name=\"ss\" type=\"float\" value=\"0.5\"/>\n"
    "    <member name=\"tt\" type=\"float\" value=\"0.25\"/>\n"
    "  </typedef>\n"
    "  <typedef name=\"pair_struct\">\n"
    "    <member name=\"a\" type=\"texcoord_struct\"/>\n"
    "    <member name=\"tint\" type=\"color3\" value=\"1, 0, 0\"/>\n"
    "  </typedef>\n";

/// A node `probe` of category `category` returning color3 from source `code`, with one input
/// `in` of `type` (written `value`, or unset when empty).
Emitted probe(const std::string& type, const std::string& value, const std::string& code,
              const std::string& extraDefinitions = "") {
  const std::string defs = kTexcoordStruct + extraDefinitions +
                           "  <nodedef name=\"ND_probe\" node=\"probe\">\n"
                           "    <input name=\"in\" type=\"" + type + "\"/>\n"
                           "    <input name=\"k\" type=\"float\" value=\"2\"/>\n"
                           "    <output name=\"out\" type=\"color3\"/>\n  </nodedef>\n"
                           "  <implementation name=\"IM_probe\" nodedef=\"ND_probe\" target=\"genglsl\" sourcecode=\"" +
                           code + "\"/>\n";
  const std::string nodes = "  <probe name=\"p\" type=\"color3\">" +
                            (value.empty() ? std::string()
                                           : "<input name=\"in\" type=\"" + type + "\" value=\"" + value + "\"/>") +
                            "</probe>\n";
  return emitted(defs, nodes, "p");
}

void expectColor(const Emitted& e, std::vector<float> expected) {
  ASSERT_TRUE(e.error.empty()) << e.error;
  ASSERT_EQ(e.color.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(e.color[i], expected[i], 1e-6f) << "component " << i;
}

TEST(InlineSource, StructMembersAreReadFromTheLiteral) {
  expectColor(probe("texcoord_struct", "{0.01;0.5}", "vec3({{in}}.ss, {{in}}.tt, 0.0)"), {0.01f, 0.5f, 0.0f});
}

TEST(InlineSource, AnUnsetStructTakesTheMemberDefaults) {
  expectColor(probe("texcoord_struct", "", "vec3({{in}}.ss, {{in}}.tt, 1.0)"), {0.5f, 0.25f, 1.0f});
}

TEST(InlineSource, NestedStructsAreReadMemberByMember) {
  expectColor(probe("pair_struct", "{{0.1;0.2};0.3, 0.4, 0.5}", "{{in}}.tint * {{in}}.a.tt + vec3({{in}}.a.ss)"),
              {0.1f + 0.3f * 0.2f, 0.1f + 0.4f * 0.2f, 0.1f + 0.5f * 0.2f});
}

TEST(InlineSource, OperatorsFollowGlslPrecedence) {
  // 1 + 2 * 3 = 7, not 9; unary minus binds tighter than *; ?: is lowest.
  expectColor(probe("float", "0.5", "vec3(1.0 + 2.0 * 3.0, -{{in}} * {{k}}, {{in}} &gt; 0.25 &amp;&amp; !({{k}} &lt; 1.0) ? 1.0 : 0.0)"),
              {7.0f, -1.0f, 1.0f});
  expectColor(probe("vector3", "0.1, 0.2, 0.3", "{{in}}.zyx * {{k}} + vec3({{in}}[1])"), {0.8f, 0.6f, 0.4f});
  expectColor(probe("vector3", "0.1, 0.2, 0.3", "vec3(mx_mod(-1.25, 1.0), mix(0.0, 4.0, 0.25), clamp({{in}}.b, 0.5, 1.0))"),
              {0.75f, 1.0f, 0.5f});
}

TEST(InlineSource, MistakesAreReportedWithTheImplementationAndTheCharacter) {
  Emitted unknownMember = probe("texcoord_struct", "{0.1;0.2}", "vec3({{in}}.uu)");
  EXPECT_NE(unknownMember.error.find("struct texcoord_struct has no member 'uu'"), std::string::npos) << unknownMember.error;
  EXPECT_NE(unknownMember.error.find("implementation 'IM_probe'"), std::string::npos) << unknownMember.error;
  EXPECT_NE(unknownMember.error.find("at character 12"), std::string::npos) << unknownMember.error;

  Emitted unknownFunction = probe("float", "0.5", "vec3(frobnicate({{in}}))");
  EXPECT_NE(unknownFunction.error.find("'frobnicate' is not a function"), std::string::npos) << unknownFunction.error;

  Emitted unknownInput = probe("float", "0.5", "vec3({{nope}})");
  EXPECT_NE(unknownInput.error.find("{{nope}} names no input of <probe> (its inputs: in, k)"), std::string::npos)
      << unknownInput.error;

  Emitted mismatch = probe("vector2", "0.5, 0.5", "{{in}} + vec3(1.0)");
  EXPECT_NE(mismatch.error.find("cannot combine a vec2 with a vec3"), std::string::npos) << mismatch.error;

  Emitted wrongType = probe("float", "0.5", "{{in}}");
  EXPECT_NE(wrongType.error.find("the expression is a float, and the node outputs a vec3"), std::string::npos)
      << wrongType.error;

  Emitted trailing = probe("float", "0.5", "vec3({{in}}) )");
  EXPECT_NE(trailing.error.find("unexpected ')' after the expression"), std::string::npos) << trailing.error;
}

TEST(InlineSource, ABuiltInGivenTooFewArgumentsIsAnErrorNotACrash) {
  // Before the fix the first argument was read before its count was checked (a crash, exit
  // 139, under every one of these).
  for (const char* call : {"sin()", "abs()", "atan()", "clamp(1.0)", "step(1.0)", "smoothstep(0.0, 1.0)", "normalize()",
                           "reflect({{in}})", "floor()", "length()", "determinant()", "cross({{in}})", "min(1.0)"}) {
    Emitted e = probe("vector3", "0.1, 0.2, 0.3", std::string("vec3(") + call + ")");
    EXPECT_NE(e.error.find("argument"), std::string::npos) << call << ": " << e.error;
    EXPECT_NE(e.error.find("given "), std::string::npos) << call << ": " << e.error;
  }
}

TEST(InlineSource, NestingDeeperThanTheLimitIsReportedAtItsPosition) {
  // 200 levels parse (GLSL written by hand never comes near); a million would overflow the stack.
  const std::string ok = std::string(199, '(') + "{{in}}" + std::string(199, ')');
  expectColor(probe("float", "0.5", "vec3" + ok), {0.5f, 0.5f, 0.5f});
  const std::string deep = std::string(1000000, '(') + "{{in}}" + std::string(1000000, ')');
  Emitted e = probe("float", "0.5", "vec3" + deep);
  EXPECT_NE(e.error.find("nests more than 200 levels"), std::string::npos) << e.error.substr(0, 300);
  // Level 1 is the whole expression, 2 vec3's argument (character 6), k + 1 the inside of the
  // k-th parenthesis: level 201 starts at character 205.
  EXPECT_NE(e.error.find("at character 205"), std::string::npos) << e.error.substr(0, 300);
  EXPECT_NE(e.error.find("... (2000010 characters)"), std::string::npos) << e.error.substr(0, 300);
  Emitted minus = probe("float", "0.5", "vec3(" + std::string(1000000, '-') + "{{in}})");
  EXPECT_NE(minus.error.find("nests more than 200 levels"), std::string::npos) << minus.error.substr(0, 300);
}

TEST(InlineSource, AConstantIndexOutsideTheVectorAndAnInfiniteLiteralAreErrors) {
  // [-1] read the last component silently; [3 - 1] is a constant and reads z.
  Emitted negative = probe("vector3", "0.1, 0.2, 0.3", "vec3({{in}}[-1])");
  EXPECT_NE(negative.error.find("index -1 is outside a vec3"), std::string::npos) << negative.error;
  EXPECT_NE(probe("vector3", "0.1, 0.2, 0.3", "vec3({{in}}[1 + 2])").error.find("index 3 is outside a vec3"), std::string::npos);
  expectColor(probe("vector3", "0.1, 0.2, 0.3", "vec3({{in}}[3 - 1])"), {0.3f, 0.3f, 0.3f});
  // 1e400 reached glslang as inf ("undeclared identifier" at a generated line).
  Emitted huge = probe("float", "0.5", "vec3(1e400 * {{in}})");
  EXPECT_NE(huge.error.find("the number 1e400 is outside the range of a 32-bit float"), std::string::npos) << huge.error;
  EXPECT_NE(huge.error.find("at character 6"), std::string::npos) << huge.error;
  expectColor(probe("float", "0.5", "vec3(1e-400 + {{in}})"), {0.5f, 0.5f, 0.5f});
}

TEST(InlineSource, BadStructLiteralsAreReportedAtTheirPosition) {
  Emitted tooFew = probe("texcoord_struct", "{0.1}", "vec3({{in}}.ss)");
  EXPECT_NE(tooFew.error.find("texcoord_struct has 2 members (ss, tt), the value gives 1"), std::string::npos)
      << tooFew.error;
  Emitted badMember = probe("pair_struct", "{{0.1;x};1, 0, 0}", "{{in}}.tint");
  EXPECT_NE(badMember.error.find("member 'tt' (float)"), std::string::npos) << badMember.error;
  // The message points at the bad member itself.
  const std::string line = "  <probe name=\"p\" type=\"color3\"><input name=\"in\" type=\"pair_struct\" value=\"{{0.1;x};1, 0, 0}\"/>";
  const std::string column = ":" + std::to_string(line.find("x};") + 1) + ": error";
  EXPECT_NE(badMember.error.find(column), std::string::npos) << column << "\n" << badMember.error;
  Emitted noBraces = probe("texcoord_struct", "0.1, 0.2", "vec3({{in}}.ss)");
  EXPECT_NE(noBraces.error.find("a texcoord_struct value is written {member;member;...} with 2 members"),
            std::string::npos)
      << noBraces.error;
}

TEST(InlineSource, AStructThatContainsItselfIsReported) {
  Emitted e = probe("float", "0.5", "vec3({{in}})",
                    "  <typedef name=\"loop_a\"><member name=\"b\" type=\"loop_b\"/></typedef>\n"
                    "  <typedef name=\"loop_b\"><member name=\"a\" type=\"loop_a\"/></typedef>\n");
  EXPECT_NE(e.error.find("contains itself"), std::string::npos) << e.error;
}

// --- MaterialX's genglsl inline implementations against mxc's rules ---

struct InlineCase {
  std::string nodedef;  ///< MaterialX's nodedef, e.g. ND_add_color3FA
  std::string category;
  std::string outputType;
  std::vector<std::pair<std::string, std::string>> inputs;  ///< name, type
  std::string sourcecode;
};

bool isVectorLike(const std::string& type) {
  return type == "float" || type == "color3" || type == "color4" || type == "vector2" || type == "vector3" ||
         type == "vector4";
}

/// Every inline genglsl implementation of MaterialX's stdlib whose node reads and returns
/// numbers and vectors (not matrices, strings or files), with its nodedef's ports.
std::vector<InlineCase> materialxInlineCases() {
  const auto libraries = sharedDir() / "conformance/materialx-tree/libraries/stdlib";
  Context context(false);
  const doc::Document* defs = context.loader.loadFile(libraries / "stdlib_defs.mtlx");
  const doc::Document* impls = context.loader.loadFile(libraries / "genglsl/stdlib_genglsl_impl.mtlx");
  std::vector<InlineCase> cases;
  if (!defs || !impls) return cases;
  for (const doc::Implementation& impl : impls->implementations) {
    if (impl.sourcecode.empty()) continue;
    for (const doc::NodeDef& nd : defs->nodedefs) {
      if (nd.name != impl.nodedef || nd.outputs.size() != 1 || !isVectorLike(std::string(nd.outputs[0].type))) continue;
      InlineCase c{std::string(nd.name), std::string(nd.node), std::string(nd.outputs[0].type), {},
                   std::string(impl.sourcecode)};
      bool usable = true;
      for (const doc::Input& in : nd.inputs) {
        const std::string type(in.type);
        if (!isVectorLike(type) && type != "integer" && type != "boolean") usable = false;
        c.inputs.emplace_back(std::string(in.name), type);
      }
      if (usable) cases.push_back(std::move(c));
    }
  }
  return cases;
}

/// A value of `type` for input number `index`: distinct, in (0.2, 0.9) so that every inline
/// function (asin, acos, ln, sqrt, pow) stays in its domain.
std::string inputValue(const std::string& type, size_t index) {
  if (type == "integer") return "1";
  if (type == "boolean") return "true";
  const int n = type == "float" ? 1 : type.back() - '0';
  std::string text;
  for (int k = 0; k < n; ++k) {
    const double x = 0.37 * static_cast<double>(index + 1) + 0.13 * (k + 1);
    text += (k ? ", " : "") + std::to_string(0.2 + 0.7 * (x - std::floor(x)));
  }
  return text;
}

TEST(InlineSource, MaterialXsInlineImplementationsAgreeWithMxcsRules) {
  const std::vector<InlineCase> cases = materialxInlineCases();
  ASSERT_GT(cases.size(), 150u) << "MaterialX's genglsl inline implementations were not found";
  int compared = 0;
  for (const InlineCase& c : cases) {
    std::string copy = "  <nodedef name=\"ND_copy\" node=\"copy\">\n";
    std::string inputs;
    for (size_t i = 0; i < c.inputs.size(); ++i) {
      const auto& [name, type] = c.inputs[i];
      copy += "    <input name=\"" + name + "\" type=\"" + type + "\"/>\n";
      inputs += "<input name=\"" + name + "\" type=\"" + type + "\" value=\"" + inputValue(type, i) + "\"/>";
    }
    std::string code = c.sourcecode;
    for (size_t at = code.find('<'); at != std::string::npos; at = code.find('<', at)) code.replace(at, 1, "&lt;");
    copy += "    <output name=\"out\" type=\"" + c.outputType + "\"/>\n  </nodedef>\n"
            "  <implementation name=\"IM_copy\" nodedef=\"ND_copy\" target=\"genglsl\" sourcecode=\"" + code + "\"/>\n";
    // Both outputs seen as color3: xyz (a float fills every channel); w on its own.
    const bool four = c.outputType.back() == '4';
    for (int part = 0; part < (four ? 2 : 1); ++part) {
      auto view = [&](const std::string& node) {
        const std::string as = part == 0 ? "<convert name=\"" + node + "_c\" type=\"color3\"><input name=\"in\" type=\"" +
                                                c.outputType + "\" nodename=\"" + node + "\"/></convert>\n"
                                          : "<extract name=\"" + node + "_w\" type=\"float\"><input name=\"in\" type=\"" +
                                                c.outputType + "\" nodename=\"" + node + "\"/><input name=\"index\" "
                                                "type=\"integer\" value=\"3\"/></extract>\n<convert name=\"" + node +
                                                "_c\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"" +
                                                node + "_w\"/></convert>\n";
        return as;
      };
      const std::string original = "  <" + c.category + " name=\"o\" type=\"" + c.outputType + "\" nodedef=\"" +
                                   c.nodedef + "\">" + inputs + "</" + c.category + ">\n" + view("o");
      const std::string inlined = "  <copy name=\"i\" type=\"" + c.outputType + "\">" + inputs + "</copy>\n" + view("i");
      const Emitted expected = emitted("", original, "o_c");
      const Emitted actual = emitted(copy, inlined, "i_c");
      if (!expected.error.empty()) continue;  // a node mxc's built-in library does not define
      ASSERT_TRUE(actual.error.empty()) << c.nodedef << " \"" << c.sourcecode << "\":\n" << actual.error;
      ASSERT_EQ(actual.color.size(), expected.color.size()) << c.nodedef;
      for (size_t k = 0; k < expected.color.size(); ++k) {
        EXPECT_NEAR(actual.color[k], expected.color[k], 1e-5f * (1.0f + std::abs(expected.color[k])))
            << c.nodedef << " \"" << c.sourcecode << "\" component " << k;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 150);
}

}  // namespace
}  // namespace mxc::test
