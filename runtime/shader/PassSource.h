// PassSource: the fragment shader texts one pass may be compiled from, prepared without GL so that
// the GL thread only compiles: the assembled text (WebGL's semantics), the plain one, and, for a
// pass whose code defines function-like macros, both expanded as browsers expand them (GCC's cpp,
// shader/BrowserPreprocess.h: a child process, kept off the GL thread). Made by planPlayer for
// every pass and the Sound pass; compilePassProgram (render/PassProgram.h) tries them in order.
// No GL needed.
#pragma once

#include <optional>
#include <string>

#include "manifest/ManifestDesc.h"
#include "shader/MacroDefines.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

struct PassSource {
    std::string text;       // rewritten to WebGL's semantics (shader/GlslRewrite.h)
    std::string plainText;  // the same without the rewrite
    // The browser-style expansion of text and plainText, for when the driver's preprocessor
    // refuses them; absent when not prepared (no function-like macro: both shaders Mesa's
    // preprocessor is known to refuse paste a macro's arguments) or when cpp refused or is missing.
    std::optional<std::string> browserText;
    std::optional<std::string> browserPlainText;
    // What `text` was rewritten from: when the driver refuses `text`, the GL thread makes it again
    // with one rule of the rewrite off at a time (render/PassProgram.cpp), a text-only step.
    RewriteParts parts;
};

// True when `code` defines a function-like macro (`#define NAME(`), the shape of every shader the
// browser-style expansion exists for.
bool definesFunctionMacro(std::string_view code);

// Assembles `pass` of `manifest` (Common included; the Sound pass with mainSound's wrapper) and,
// when its code or Common defines a function-like macro, expands it as browsers do (runs cpp).
// `defines`: the run's --define macros, in every pass.
PassSource preparePassSource(const ManifestDesc& manifest, const PassDesc& pass, std::span<const MacroDefine> defines = {});

}  // namespace toyhost
