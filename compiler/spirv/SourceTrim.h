#pragma once
/// \file
/// The text glslang parses: a shader's GLSL without what cannot reach its SPIR-V.
///
/// A material's shader is the whole shader library (about 1,900 lines, half of its bytes
/// comments) specialised by #defines, of which a material calls a fraction. glslang reads every
/// character: it scans comments and the branches its preprocessor skips, and parses and checks
/// every function before it drops those the entry point never calls (glslang removes uncalled
/// functions before writing SPIR-V). Parsing is a third of a batch's instructions. Trimming
/// takes out, before glslang sees the text:
///  - comments, and the indentation and trailing blanks of every line;
///  - the branches of #if/#ifdef/#ifndef/#elif/#else that are not taken, and the conditional
///    directives themselves (evaluated here: `defined`, `!`, `&&`, `||`, parentheses and integers
///    on macros named MXC_..., the only ones the library tests);
///  - every function definition that nothing left can call: a function is kept when its name
///    appears in `main`, in a kept function, in any declaration outside a function or in any
///    directive (a macro's body), so overloads are kept or removed together; a definition with
///    a directive inside it, or text before it that is not its own (a macro invoked without a
///    `;`), is kept.
/// glslang would have removed those functions itself; their absence changes nothing in the
/// SPIR-V, which ShaderGroupTest and the golden tests check byte for byte.
///
/// Every line stays on its line (removed text keeps its newlines), so glslang's messages name
/// the lines of the text mxc wrote. Text the trim cannot follow (a conditional on another macro,
/// an expression with a comparison, an unterminated comment or conditional, a directive inside a
/// function body that could be removed) is returned unchanged: trimming saves time and never
/// decides whether a shader compiles.

#include <cstddef>
#include <string>
#include <string_view>

namespace mxc::spirv {

struct TrimmedSource {
  std::string text;
  /// False when the text was returned unchanged (see above).
  bool trimmed = false;
  size_t functionsRemoved = 0;
};

TrimmedSource trimForParse(std::string_view glsl);

}  // namespace mxc::spirv
