#include "compiler/glsl/ShaderGroup.h"

#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

namespace mxc::glsl {

namespace {

/// The lines of a shader's text.
std::vector<std::string_view> splitLines(const std::string& text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(std::string_view(text).substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

/// A line without its comment (a texture declaration's names the member's file).
std::string_view code(std::string_view line) { return line.substr(0, line.find("//")); }

}  // namespace

std::string groupMemberFunction(size_t index) { return fmt::format("{}_m{}", kClosureFunction, index); }

spirv::GlslSource groupSource(const std::vector<const MaterialShader*>& members) {
  if (members.empty()) throw std::logic_error("a shader group without members");
  const MaterialShader& first = *members.front();
  const std::vector<std::string_view> lines = splitLines(first.glsl.text);
  // The closure's first line is its signature, as ShaderBuilder writes it.
  const std::string signature = fmt::format("void {}({}) {{", kClosureFunction, kClosureParameters);
  if (first.closureEnd <= first.closureFirst || first.closureEnd > lines.size() || lines[first.closureFirst] != signature) {
    throw std::logic_error("a material shader without its closure function's lines");
  }
  spirv::GlslSource out;
  out.stage = first.glsl.stage;
  out.name = fmt::format("{} materials of one library ({} first)", members.size(), first.glsl.name);
  auto add = [&](std::string_view line) {
    out.text += line;
    out.text += '\n';
  };
  // Every member declares its textures before its closure, the same lines but for their
  // comments, as many as it reads (ShaderBuilder.h: MaterialShader::libraryKey); the group's are
  // those of the member that reads the most. The lines are compared below, member by member.
  auto textureCount = [](const MaterialShader& m) { return m.texturesEnd - m.texturesFirst; };
  const MaterialShader* mostTextures = &first;
  for (const MaterialShader* m : members) {
    if (m->texturesFirst > m->texturesEnd || m->texturesEnd > m->closureFirst) {
      throw std::logic_error("a material shader whose texture declarations are not before its closure");
    }
    if (textureCount(*m) > textureCount(*mostTextures)) mostTextures = m;
  }
  const std::vector<std::string_view> textureLines =
      mostTextures == &first ? lines : splitLines(mostTextures->glsl.text);
  if (mostTextures->texturesEnd > textureLines.size()) {
    throw std::logic_error("a material shader without its texture declarations' lines");
  }
  for (size_t i = 0; i < first.texturesFirst; ++i) add(lines[i]);
  for (size_t i = mostTextures->texturesFirst; i < mostTextures->texturesEnd; ++i) add(textureLines[i]);
  for (size_t i = first.texturesEnd; i < first.closureFirst; ++i) add(lines[i]);
  for (size_t k = 0; k < members.size(); ++k) {
    const MaterialShader& m = *members[k];
    if (m.libraryKey != first.libraryKey) throw std::logic_error("a shader group of different libraries");
    const std::vector<std::string_view> own = splitLines(m.glsl.text);
    if (m.closureEnd > own.size() || own[m.closureFirst] != signature) {
      throw std::logic_error("a material shader without its closure function's lines");
    }
    for (size_t i = 0; i < textureCount(m); ++i) {
      if (code(own[m.texturesFirst + i]) != code(textureLines[mostTextures->texturesFirst + i])) {
        throw std::logic_error("a shader group whose members declare a texture differently");
      }
    }
    add(fmt::format("void {}({}) {{", groupMemberFunction(k), kClosureParameters));
    for (size_t i = m.closureFirst + 1; i < m.closureEnd; ++i) add(own[i]);
  }
  add(signature);
  for (size_t k = 0; k < members.size(); ++k) add(fmt::format("  {}({});", groupMemberFunction(k), kClosureArguments));
  add("}");
  for (size_t i = first.closureEnd; i < lines.size(); ++i) add(lines[i]);
  return out;
}

}  // namespace mxc::glsl
