#pragma once
// The fuzzed entry points, shared by the libFuzzer programs (XmlFuzz.cpp, CompileFuzz.cpp,
// built with scripts/fuzz) and by the regression test that replays the seed corpus and every
// input the fuzzers found (FuzzRegressionTest.cpp, in the normal suite).
//
// Each target must return normally for any input: an error is a diagnostic or a CompileError,
// never a crash, a hang, an uncaught exception or (under the sanitizers) undefined behaviour.

#include <cstddef>
#include <cstdint>

namespace mxc::fuzz {

/// The XML parser alone.
void parseXml(const uint8_t* data, size_t size);

/// The whole front end and the GLSL back end: document model, resolution against the built-in
/// library, lowering, passes, effects and the shaders of every kind (glslang is not run: it is
/// not ours, and it is slow per input).
void compileDocument(const uint8_t* data, size_t size);

/// Inline source implementations (compiler/lower/InlineSource.cpp): the bytes are the
/// `sourcecode` of a node's implementation (made XML-safe), for a float and a vector3 output
/// with inputs of several types, compiled as compileDocument compiles.
void compileInlineSource(const uint8_t* data, size_t size);

/// A scene file's text (cli/Scene.cpp), read and checked as `mxc render SCENE.json` does.
void readSceneJson(const uint8_t* data, size_t size);

/// A mesh file's bytes (runtime/MeshFile.cpp): a binary glTF when they start with its magic,
/// a glTF when its first non-blank byte is '{', an OBJ otherwise.
void loadMeshFile(const uint8_t* data, size_t size);

}  // namespace mxc::fuzz
