// Builds the GLSL ES 3.00 fragment shader a pass becomes on shadertoy.com (header, uniforms,
// main() wrapper, then Common, then the pass code), numbered so that compiler messages map back
// to the user's files and lines (shader/CompilerLog.h). Pure text work; no GL needed.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>

#include "manifest/ManifestDesc.h"
#include "shader/GlslRewrite.h"
#include "shader/MacroDefines.h"

namespace toyhost {

struct ShaderInputs {
    PassId pass = PassId::Image;
    bool sound = false;                    // the Sound pass (mainSound); `pass` is then ignored
    const std::string* common = nullptr;   // null: the shadertoy has no Common pass
    std::string_view code;
    std::array<SamplerType, kChannelCount> samplers{};
    // The run's --define macros, written after the header (in its line numbering), before Common.
    std::span<const MacroDefine> defines;
};

// The generated text numbers its parts apart with #line, so a compiler message's line number
// alone says which part it is in: the header from kHeaderLineBase, Common from kCommonLineBase
// and the pass code from 1, exactly as the user's file numbers it (a user's own #line in the pass
// keeps working as the user meant it). The site numbers lines through the whole concatenated
// text; only __LINE__ can tell the difference.
inline constexpr int kHeaderLineBase = 2000000;
inline constexpr int kCommonLineBase = 1000000;

// What the rewrite of a pass works from, kept so that the text can be made again with some of its
// rules off when the driver refuses it (render/PassProgram.cpp).
struct RewriteParts {
    std::string header;           // the generated header, not rewritten
    std::string user;             // Common and the pass, numbered (#line), before the rewrite
    GlslRewriteOptions options;   // every rule on
};

// The header followed by the user's text rewritten with `options`.
std::string rewrittenShader(const RewriteParts& parts, const GlslRewriteOptions& options);

struct AssembledShader {
    std::string text;        // rewritten to WebGL's semantics (shader/GlslRewrite.h)
    std::string plainText;   // the same without the rewrite
    bool hasCommon = false;
    RewriteParts parts;      // text is rewrittenShader(parts, parts.options)
};

AssembledShader assembleFragmentShader(const ShaderInputs& inputs);

// The Image pass's main() calls mainImage with gl_FragCoord.xy plus this uniform (vec2, pixels):
// zero (GL's initial value) draws the site's pixel centres exactly; supersampling and tiles set it
// per draw. The pass's own reads of gl_FragCoord are of kFragCoordCopy, gl_FragCoord moved by the
// same offset (the rewrite renames them), so a shader that reads it directly is sampled and tiled
// as well.
inline constexpr const char* kFragOffsetUniform = "toyhost_fragOffset";
inline constexpr const char* kFragCoordCopy = "toyhost_FragCoord";

// The vertex shader every pass shares: one triangle that covers the viewport.
const char* fullscreenVertexShader();

struct SourceLine {
    enum class Part { Header, Common, Pass };
    Part part = Part::Header;
    int line = 0;              // 1-based line within that part
};

// Which part a line number in a compiler message belongs to (see kHeaderLineBase).
SourceLine mapGeneratedLine(int reportedLine);

}  // namespace toyhost
