// Builds the GLSL ES 3.00 fragment shader a pass becomes on shadertoy.com (header, uniforms,
// main() wrapper, then Common, then the pass code) and maps compiler messages back to the
// user's files and lines. Pure text work; no GL needed.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// Sampler type of an iChannel uniform. Unbound channels are sampler2D.
enum class SamplerType { Sampler2D, SamplerCube, Sampler3D };

struct ShaderInputs {
    PassId pass = PassId::Image;
    const std::string* common = nullptr;   // null: the shadertoy has no Common pass
    std::string_view code;
    std::array<SamplerType, kChannelCount> samplers{};
};

struct AssembledShader {
    std::string text;
    int headerLines = 0;       // lines 1..headerLines are the generated header
    int commonLines = 0;       // lines of Common (0 without Common)
    int passFirstLine = 1;     // generated line where the pass code's line 1 is
};

AssembledShader assembleFragmentShader(const ShaderInputs& inputs);

// The vertex shader every pass shares: one triangle that covers the viewport.
const char* fullscreenVertexShader();

struct SourceLine {
    enum class Part { Header, Common, Pass };
    Part part = Part::Header;
    int line = 0;              // 1-based line within that part
};

SourceLine mapGeneratedLine(const AssembledShader& shader, int generatedLine);

// Rewrites a compiler info log so each message points at the user's file and line:
// "0:57(12): error: ..." becomes "<passFile>:40:12: error: ..." (or "<commonFile>:...").
// Understands Mesa's "S:L(C):", ANGLE/glslang's "ERROR: S:L:" and NVIDIA's "S(L) :" forms.
std::string translateCompilerLog(const AssembledShader& shader, std::string_view log,
                                 const std::string& commonFile, const std::string& passFile);

}  // namespace toyhost
