// Malformed documents at the model and graph level: each case asserts the line, column and
// message of the first error reported while loading and resolving against the built-in library.

#include <gtest/gtest.h>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

struct Malformed {
  const char* name;
  std::string text;  // the whole document
  uint32_t line;
  uint32_t column;
  const char* message;
};

void PrintTo(const Malformed& m, std::ostream* os) { *os << m.name; }

// mtlx() puts the body on line 3 onwards.
const Malformed kCases[] = {
    {"RootIsNotMaterialx", "<foo/>", 1, 1, "the root element is <foo>"},
    {"UnknownInput",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in3\" type=\"float\" value=\"1\"/>\n  </add>\n"), 4, 5,
     "it has no input 'in3' (its inputs: in1, in2)"},
    {"InputTypeFitsNoDefinition",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"color3\" value=\"1,1,1\"/>\n  </add>\n"), 4, 5,
     "its input 'in1' has type float, not color3"},
    {"NoDefinitionForOutputType", mtlx("  <multiply name=\"m\" type=\"string\"/>\n"), 3, 28,
     "<multiply> has no definition with output type string"},
    {"DanglingNodename",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"nothere\"/>\n  </add>\n"), 4,
     46, "'in1' connects to node 'nothere', which does not exist in the document"},
    {"ConnectionTypeMismatch",
     mtlx("  <constant name=\"c\" type=\"color3\"/>\n  <add name=\"a\" type=\"float\">\n"
          "    <input name=\"in1\" type=\"float\" nodename=\"c\"/>\n  </add>\n"),
     5, 46, "type mismatch: 'in1' is float, but output 'out' of node 'c' is color3"},
    {"Cycle",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"b\"/>\n  </add>\n"
          "  <add name=\"b\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"a\"/>\n  </add>\n"),
     7, 5, "cycle: a -> b -> a"},
    {"SelfCycle", mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in2\" type=\"float\" nodename=\"a\"/>\n  </add>\n"),
     4, 5, "cycle: a -> a (through input 'in2' of node 'a')"},
    {"MissingNodeGraph",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodegraph=\"NG_x\" output=\"o\"/>\n"
          "  </add>\n"),
     4, 47, "'in1' connects to node graph 'NG_x', which does not exist"},
    {"MissingGraphOutput",
     mtlx("  <nodegraph name=\"NG\">\n    <constant name=\"c\" type=\"float\"/>\n"
          "    <output name=\"o\" type=\"float\" nodename=\"c\"/>\n  </nodegraph>\n"
          "  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodegraph=\"NG\" output=\"nope\"/>\n"
          "  </add>\n"),
     8, 59, "node graph 'NG' has no output 'nope' (its outputs: o)"},
    {"AmbiguousGraphOutput",
     mtlx("  <nodegraph name=\"NG\">\n    <constant name=\"c\" type=\"float\"/>\n"
          "    <output name=\"o1\" type=\"float\" nodename=\"c\"/>\n    <output name=\"o2\" type=\"float\" nodename=\"c\"/>\n"
          "  </nodegraph>\n  <add name=\"a\" type=\"float\">\n"
          "    <input name=\"in1\" type=\"float\" nodegraph=\"NG\"/>\n  </add>\n"),
     9, 47, "node graph 'NG' has several outputs (o1, o2)"},
    {"MissingInterfaceInput",
     mtlx("  <nodegraph name=\"NG\">\n    <add name=\"a\" type=\"float\">\n"
          "      <input name=\"in1\" type=\"float\" interfacename=\"gain\"/>\n    </add>\n"
          "    <output name=\"o\" type=\"float\" nodename=\"a\"/>\n  </nodegraph>\n"),
     5, 53, "'in1' refers to interface input 'gain', which node graph 'NG' does not have"},
    {"InterfaceTheDocumentDoesNotHave",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" interfacename=\"x\"/>\n  </add>\n"), 4,
     51, "refers to interface input 'x', which the document does not have (its interface: empty)"},
    {"InterfaceTypeMismatch",
     mtlx("  <nodegraph name=\"NG\">\n    <input name=\"gain\" type=\"color3\" value=\"1,1,1\"/>\n"
          "    <add name=\"a\" type=\"float\">\n      <input name=\"in1\" type=\"float\" interfacename=\"gain\"/>\n"
          "    </add>\n    <output name=\"o\" type=\"float\" nodename=\"a\"/>\n  </nodegraph>\n"),
     6, 53, "type mismatch: 'in1' is float, but interface input 'gain' of node graph 'NG' is color3"},
    {"UnknownNodedefAttribute", mtlx("  <add name=\"a\" type=\"float\" nodedef=\"ND_nope\"/>\n"), 3, 39,
     "node 'a' names nodedef 'ND_nope', which is not defined"},
    {"NodedefAttributeTypeMismatch", mtlx("  <add name=\"a\" type=\"color3\" nodedef=\"ND_add_float\"/>\n"), 3, 23,
     "node 'a' has type color3, but nodedef 'ND_add_float' outputs float"},
    {"UnknownVersion", mtlx("  <standard_surface name=\"s\" type=\"surfaceshader\" version=\"9.9\"/>\n"), 3, 60,
     "<standard_surface> has no version 9.9"},
    {"EnumValueNotAllowed",
     mtlx("  <dielectric_bsdf name=\"d\" type=\"BSDF\">\n    <input name=\"scatter_mode\" type=\"string\" value=\"X\"/>\n"
          "  </dielectric_bsdf>\n"),
     4, 53, "'scatter_mode' is \"X\", which is not one of its allowed values: R,T,RT"},
    {"MultiOutputWithoutOutputName",
     mtlx("  <separate3 name=\"s\" type=\"multioutput\"/>\n  <add name=\"a\" type=\"float\">\n"
          "    <input name=\"in1\" type=\"float\" nodename=\"s\"/>\n  </add>\n"),
     5, 46, "node 's' has several outputs (outr, outg, outb); name one with output=\"...\""},
    {"MultiOutputWrongOutputName",
     mtlx("  <separate3 name=\"s\" type=\"multioutput\"/>\n  <add name=\"a\" type=\"float\">\n"
          "    <input name=\"in1\" type=\"float\" nodename=\"s\" output=\"outq\"/>\n  </add>\n"),
     5, 57, "node 's' has no output 'outq' (its outputs: outr, outg, outb)"},
    {"ChannelsIn139",
     mtlx("  <constant name=\"c\" type=\"color3\"/>\n  <add name=\"a\" type=\"float\">\n"
          "    <input name=\"in1\" type=\"float\" nodename=\"c\" channels=\"r\"/>\n  </add>\n"),
     5, 59, "the 'channels' attribute is MaterialX 1.38-and-older syntax, removed in 1.39"},
    {"ChannelsNotAChannel",
     "<materialx version=\"1.38\">\n  <constant name=\"c\" type=\"color3\"/>\n  <add name=\"a\" type=\"float\">\n"
     "    <input name=\"in1\" type=\"float\" nodename=\"c\" channels=\"q\"/>\n  </add>\n</materialx>\n",
     4, 59, "'q' is not a channel of a color3"},
    {"ChannelsWrongCount",
     "<materialx version=\"1.38\">\n  <constant name=\"c\" type=\"color3\"/>\n  <add name=\"a\" type=\"float\">\n"
     "    <input name=\"in1\" type=\"float\" nodename=\"c\" channels=\"rg\"/>\n  </add>\n</materialx>\n",
     4, 59, "a float needs 1 channel, \"rg\" gives 2"},
    {"InvalidFloat",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" value=\"abc\"/>\n  </add>\n"), 4, 43,
     "invalid float value \"abc\" for 'in1': 'abc' is not a number"},
    {"WrongComponentCount",
     mtlx("  <add name=\"a\" type=\"color3\">\n    <input name=\"in1\" type=\"color3\" value=\"1, 2\"/>\n  </add>\n"), 4, 44,
     "a color3 value needs 3 numbers, found 2"},
    {"BadComponentPointsInsideValue",
     mtlx("  <add name=\"a\" type=\"color3\">\n    <input name=\"in1\" type=\"color3\" value=\"1, x, 3\"/>\n  </add>\n"), 4, 47,
     "'x' is not a number"},
    {"BadBoolean",
     mtlx("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
          "    <input name=\"geometry_thin_walled\" type=\"boolean\" value=\"yes\"/>\n  </open_pbr_surface>\n"),
     4, 62, "'yes' is not a boolean (write true or false)"},
    {"IntegerOverflow",
     mtlx("  <add name=\"a\" type=\"integer\">\n    <input name=\"in1\" type=\"integer\" value=\"99999999999\"/>\n  </add>\n"),
     4, 45, "'99999999999' does not fit a 32-bit integer"},
    {"NonFiniteFloat",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" value=\"inf\"/>\n  </add>\n"), 4, 43,
     "'inf' is not a finite number"},
    {"FloatOutOfRange",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" value=\"1e40\"/>\n  </add>\n"), 4, 43,
     "'1e40' is out of the range of a 32-bit float"},
    {"ValueOnClosureType",
     mtlx("  <surface name=\"s\" type=\"surfaceshader\">\n    <input name=\"bsdf\" type=\"BSDF\" value=\"1\"/>\n  </surface>\n"),
     4, 43, "this type has no literal values"},
    {"NodeWithoutName", mtlx("  <add type=\"float\"/>\n"), 3, 3, "<add> has no 'name' attribute"},
    {"InputWithoutType", mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" value=\"1\"/>\n  </add>\n"), 4, 5,
     "has no 'type' attribute (every input and output declares its type)"},
    {"NodeWithoutType", mtlx("  <add name=\"a\"/>\n"), 3, 3, "has no 'type' attribute (a node declares its output type)"},
    {"InvalidName", mtlx("  <add name=\"a b\" type=\"float\"/>\n"), 3, 14, "invalid name 'a b'"},
    {"DuplicateNodeName", mtlx("  <add name=\"a\" type=\"float\"/>\n  <add name=\"a\" type=\"float\"/>\n"), 4, 3,
     "duplicate name 'a' in the document (first defined at line 3, column 3)"},
    {"DuplicateInputName",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" value=\"1\"/>\n"
          "    <input name=\"in1\" type=\"float\" value=\"2\"/>\n  </add>\n"),
     5, 5, "duplicate name 'in1' in this node"},
    {"DuplicateInGraph",
     mtlx("  <nodegraph name=\"NG\">\n    <input name=\"x\" type=\"float\"/>\n    <constant name=\"x\" type=\"float\"/>\n"
          "    <output name=\"o\" type=\"float\" nodename=\"x\"/>\n  </nodegraph>\n"),
     5, 5, "duplicate name 'x' in node graph 'NG'"},
    {"Parameter137", mtlx("  <add name=\"a\" type=\"float\">\n    <parameter name=\"in1\" type=\"float\" value=\"1\"/>\n  </add>\n"), 4,
     5, "<parameter> is MaterialX 1.37 syntax"},
    {"ParameterAtDocumentLevel", mtlx("  <parameter name=\"x\" type=\"float\"/>\n"), 3, 3,
     "<parameter> is MaterialX 1.37 syntax"},
    {"DocumentInputNameTakenByANode",
     mtlx("  <input name=\"x\" type=\"float\" value=\"1\"/>\n  <constant name=\"x\" type=\"float\"/>\n"), 4, 3,
     "'x'"},
    {"NestedNodeGraph",
     mtlx("  <nodegraph name=\"NG\">\n    <nodegraph name=\"inner\"/>\n    <output name=\"o\" type=\"float\" value=\"1\"/>\n"
          "  </nodegraph>\n"),
     4, 5, "<nodegraph> is not allowed inside a node graph"},
    {"UnexpectedChildOfNode", mtlx("  <add name=\"a\" type=\"float\">\n    <add name=\"b\" type=\"float\"/>\n  </add>\n"), 4, 5,
     "unexpected <add> inside <add>"},
    {"NodenameAndNodegraph",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"b\" nodegraph=\"NG\"/>\n"
          "  </add>\n"),
     4, 60, "'in1' connects to both node 'b' and node graph 'NG'"},
    {"InterfaceAndNodename",
     mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"b\" interfacename=\"x\"/>\n"
          "  </add>\n"),
     4, 64, "'in1' has both an interfacename and a node connection"},
    {"ImplementationOfMissingGraph",
     mtlx("  <implementation name=\"IM\" nodedef=\"ND_add_float\" nodegraph=\"NG_missing\"/>\n"), 3, 3,
     "implementation 'IM' names node graph 'NG_missing', which is not defined"},
    {"ImplementationOfMissingNodedef",
     mtlx("  <nodegraph name=\"NG\">\n    <output name=\"out\" type=\"float\" value=\"1\"/>\n  </nodegraph>\n"
          "  <implementation name=\"IM\" nodedef=\"ND_missing\" nodegraph=\"NG\"/>\n"),
     6, 3, "implementation 'IM' is for nodedef 'ND_missing', which is not defined"},
    {"InheritMissing",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\" inherit=\"ND_base\">\n    <output name=\"out\" type=\"float\"/>\n"
          "  </nodedef>\n"),
     3, 3, "nodedef 'ND_x' inherits from 'ND_base', which is not defined"},
    {"InheritCycle",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\" inherit=\"ND_y\">\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"
          "  <nodedef name=\"ND_y\" node=\"y\" inherit=\"ND_x\">\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"),
     3, 3, "nodedef 'ND_x' inherits from itself"},
    {"NodedefWithoutOutput", mtlx("  <nodedef name=\"ND_x\" node=\"x\">\n    <input name=\"a\" type=\"float\"/>\n  </nodedef>\n"),
     3, 3, "nodedef 'ND_x' declares no <output> and inherits none"},
    {"NodedefInputUnknownType",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\">\n    <input name=\"a\" type=\"colour3\"/>\n"
          "    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"),
     4, 5, "input 'a' of nodedef 'ND_x' has unknown type 'colour3'"},
    {"NodedefUnknownGeomProp",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\">\n    <input name=\"n\" type=\"vector3\" defaultgeomprop=\"Nmodel\"/>\n"
          "    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"),
     4, 53, "defaults to geometric property 'Nmodel', which no geompropdef defines"},
    {"GraphImplementsMissingNodedef",
     mtlx("  <nodegraph name=\"NG\" nodedef=\"ND_missing\">\n    <output name=\"out\" type=\"float\" value=\"1\"/>\n"
          "  </nodegraph>\n"),
     3, 3, "node graph 'NG' implements nodedef 'ND_missing', which is not defined"},
    {"GraphImplementationLacksOutput",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\">\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"
          "  <nodegraph name=\"NG\" nodedef=\"ND_x\">\n    <output name=\"result\" type=\"float\" value=\"1\"/>\n"
          "  </nodegraph>\n"),
     6, 3, "node graph 'NG' implements nodedef 'ND_x' but has no output 'out'"},
    {"GraphImplementationDeclaresInputs",
     mtlx("  <nodegraph name=\"NG\" nodedef=\"ND_add_float\">\n    <input name=\"in1\" type=\"float\"/>\n"
          "    <output name=\"out\" type=\"float\" value=\"1\"/>\n  </nodegraph>\n"),
     4, 5, "cannot declare inputs of its own"},
    {"GraphConnectsToGraphFromInside",
     mtlx("  <nodegraph name=\"A\">\n    <output name=\"o\" type=\"float\" value=\"1\"/>\n  </nodegraph>\n"
          "  <nodegraph name=\"B\">\n    <add name=\"a\" type=\"float\">\n"
          "      <input name=\"in1\" type=\"float\" nodegraph=\"A\"/>\n    </add>\n"
          "    <output name=\"o\" type=\"float\" nodename=\"a\"/>\n  </nodegraph>\n"),
     8, 49, "only document-level elements can connect to a node graph"},
    {"IncludeWithoutHref", mtlx("  <xi:include/>\n"), 3, 3, "<xi:include> has no 'href' attribute"},
    {"IncludeMissingFile", mtlx("  <xi:include href=\"no_such_file.mtlx\"/>\n"), 3, 21,
     "cannot read the included file"},
    {"BadIsDefaultVersion",
     mtlx("  <nodedef name=\"ND_x\" node=\"x\" isdefaultversion=\"maybe\">\n    <output name=\"out\" type=\"float\"/>\n"
          "  </nodedef>\n"),
     3, 51, "'isdefaultversion' must be true or false, not 'maybe'"},
    {"BadUnitScale",
     mtlx("  <unitdef name=\"UD\" unittype=\"distance\">\n    <unit name=\"league\" scale=\"far\"/>\n  </unitdef>\n"), 4, 32,
     "invalid unit scale: 'far' is not a number"},
    {"UnknownGraphInterfaceType",
     mtlx("  <nodegraph name=\"NG\">\n    <input name=\"x\" type=\"colour3\"/>\n"
          "    <output name=\"o\" type=\"float\" value=\"1\"/>\n  </nodegraph>\n"),
     4, 27, "interface input 'x' has unknown type 'colour3'"},
};

class ResolverErrors : public ::testing::TestWithParam<Malformed> {};

TEST_P(ResolverErrors, ReportsPositionAndMessage) {
  const Malformed& m = GetParam();
  Context context;
  context.resolve(m.text);
  Diagnostic first = context.firstError();
  ASSERT_FALSE(first.message.empty()) << "expected an error; got:\n" << context.diagnostics.format();
  ASSERT_TRUE(first.location.valid()) << first.format();
  EXPECT_EQ(first.location.file->path(), "test.mtlx");
  LineColumn lc = first.location.lineColumn();
  EXPECT_EQ(lc.line, m.line) << first.format();
  EXPECT_EQ(lc.column, m.column) << first.format();
  EXPECT_NE(first.message.find(m.message), std::string::npos) << "message was: " << first.message;
}

INSTANTIATE_TEST_SUITE_P(Cases, ResolverErrors, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Malformed>& param) { return std::string(param.param.name); });

// A node of a category no nodedef defines is read with a warning at its position (MaterialX
// reads and validates such a node; its test suite has some: lights/light_rig_test_1.mtlx without
// the harness's light library), saying what was probably meant.
const Malformed kUnknownCategories[] = {
    {"WithSuggestion", mtlx("  <multipy name=\"m\" type=\"float\"/>\n"), 3, 3,
     "unknown node category <multipy>: no nodedef defines it (did you mean <multiply>?)"},
    {"Plain", mtlx("  <frobnicate name=\"m\" type=\"float\"/>\n"), 3, 3,
     "unknown node category <frobnicate>: no nodedef defines it"},
    {"NamespacedCategoryWrittenPlain",
     mtlx("  <nodedef name=\"ND_t\" node=\"t\" namespace=\"acme\">\n    <output name=\"out\" type=\"float\"/>\n"
          "  </nodedef>\n  <t name=\"x\" type=\"float\"/>\n"),
     6, 3, "unknown node category <t>: no nodedef defines it (<t> is defined in namespace 'acme': write <acme:t>)"},
    {"NodeDefWritingNodename",
     mtlx("  <nodedef name=\"ND_p\" nodename=\"p\">\n    <output name=\"out\" type=\"float\"/>\n"
          "  </nodedef>\n  <p name=\"x\" type=\"float\"/>\n"),
     6, 3, "unknown node category <p>: no nodedef defines it (nodedef 'ND_p' at test.mtlx:3:3 writes nodename=\"p\"; the attribute is node=\"p\")"},
};

class UnknownCategories : public ::testing::TestWithParam<Malformed> {};

TEST_P(UnknownCategories, AreAWarningAtTheirPosition) {
  const Malformed& m = GetParam();
  Context context;
  context.resolve(m.text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const Diagnostic* warning = nullptr;
  for (const Diagnostic& d : context.diagnostics.all()) {
    if (d.severity == Severity::Warning && d.message.find(m.message) != std::string::npos) warning = &d;
  }
  ASSERT_NE(warning, nullptr) << context.diagnostics.format();
  LineColumn lc = warning->location.lineColumn();
  EXPECT_EQ(lc.line, m.line) << warning->format();
  EXPECT_EQ(lc.column, m.column) << warning->format();
}

INSTANTIATE_TEST_SUITE_P(Cases, UnknownCategories, ::testing::ValuesIn(kUnknownCategories),
                         [](const ::testing::TestParamInfo<Malformed>& param) { return std::string(param.param.name); });

// A node graph implementing a nodedef that has no `node` attribute implements it: the nodedef is
// defined by its name (MaterialX's definition_reduced_interface.mtlx; mxc called it undefined).
TEST(Resolver, ANodeGraphImplementsANodeDefWithoutCategory) {
  Context context;
  context.resolve(mtlx("  <nodedef name=\"ND_p\">\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"
                       "  <nodegraph name=\"NG_p\" nodedef=\"ND_p\">\n"
                       "    <output name=\"out\" type=\"float\" value=\"1\"/>\n  </nodegraph>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
}

}  // namespace
}  // namespace mxc::test
