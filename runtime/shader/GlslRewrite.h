// GlslRewrite: the source rewrite that gives a GLSL ES 3.00 shader WebGL's semantics on a desktop
// driver: locals declared without an initialiser become zero at every execution of the
// declaration and `out` parameters zero at every call (ANGLE does both; Mesa's glsl_zero_init only
// once per invocation), dynamic indices clamped into range (shader/IndexClamp.h), undefined integer constants given
// ANGLE's values (shader/IntegerConstantFold.h), and identifiers Mesa reserves but browsers accept are renamed. Every
// insertion stays on its line, so compiler messages keep the user's line numbers. Pure text work.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace toyhost {

// `text` (a whole fragment shader, or any run of GLSL) rewritten as above. A local declared by a
// macro is zeroed after its statement and an index in a macro body is clamped in the body, as the
// browser treats the expanded text (shader/MacroTable.h). Declarations it cannot read (a type it
// does not know) are left as they are; when the braces do not balance outside preprocessor lines
// it only renames.
// With `promote`, the precision qualifiers named there (`lowp`, `mediump`) are written `highp` in
// the code and in `#define` bodies (never in `#ifdef`, `#if defined`, `#undef` or a macro's name),
// so they compute in 32 bits as on desktop GPUs while `#ifdef lowp` stays false as in WebGL.
// With `clampIndices`, dynamic array, vector and matrix indices are clamped as ANGLE does.
// With `foldIntegerConstants`, integer constant operations GLSL leaves undefined (division by 0,
// INT_MIN / -1, `%` of negatives, shifts past 31) are written as the value ANGLE folds them to
// (shader/IntegerConstantFold.h), on scalars and vectors, with constants written as macros too.
// With `foldFloatConstants`, a float built-in call on constants that ANGLE folds to a value of its
// own (0 for arguments GLSL leaves undefined, round() half away from zero) is written as that value
// (shader/FloatConstantFold.h).
// With `preciseInverseTrig`, every `asin` and `acos` is `toyhost_asin` / `toyhost_acos`, the
// header's versions (shader/ShaderAssembly.cpp: preciseInverseTrigFunctions) through atan, except
// where GLSL requires a constant expression (outside function bodies, a `const` declaration, an
// array size), where a user function is not constant: there a call of a float literal is written
// as the value ANGLE folds it to (C's asinf/acosf), any other call is left to the driver.
// With `opaqueDivisors`, every divisor inside a function body is hidden from Mesa's constant folder
// (shader/OpaqueDivisors.h), so a division by a zero it could see is the IEEE one, as in the browser.
// Without `zeroInit`, `rename`, `clampIndices`, `foldIntegerConstants`, `foldFloatConstants`, `preciseInverseTrig` and `opaqueDivisors` only the promotion is done (the text a driver gets when it
// refuses every rule; render/PassProgram.cpp turns them off one at a time, with a warning each).
// With `fragCoord`, every `gl_FragCoord` of the text (directives included) is that name instead: the
// Image pass reads a copy moved by the sample's or tile's offset (shader/ShaderAssembly.h).
// The rules of the rewrite a driver's refusal can turn off one by one (render/PassProgram.cpp),
// each named in the warning that says it was skipped.
enum class RewriteRule { ZeroInit, ClampIndices, FoldIntegerConstants, FoldFloatConstants, PreciseInverseTrig, OpaqueDivisors, Rename };
inline constexpr RewriteRule kRewriteRules[] = {RewriteRule::ZeroInit,           RewriteRule::ClampIndices,
                                                RewriteRule::FoldIntegerConstants, RewriteRule::FoldFloatConstants,
                                                RewriteRule::PreciseInverseTrig, RewriteRule::OpaqueDivisors,
                                                RewriteRule::Rename};
const char* rewriteRuleName(RewriteRule rule);  // "zeroInit", "clampIndices", ...
// What the shader loses when `rule` is off, in a few words for the warning.
const char* rewriteRuleEffect(RewriteRule rule);

struct GlslRewriteOptions {
    bool lowp = false;
    bool mediump = false;
    bool zeroInit = true;
    bool rename = true;
    bool clampIndices = true;
    bool foldIntegerConstants = true;
    bool foldFloatConstants = true;
    bool preciseInverseTrig = true;
    bool opaqueDivisors = true;
    std::string_view fragCoord;
    // For tests only: the named rule, when on, also writes a statement every driver refuses at the
    // end of the text (on its last line), so the tests of the fallback (render/PassProgram.h) can
    // make exactly that rule fail.
    std::optional<RewriteRule> plantedFailure;
};
std::string rewriteLikeWebGL(std::string_view text, GlslRewriteOptions options = {});

// The switch of `rule` in `options`.
bool& ruleSwitch(GlslRewriteOptions& options, RewriteRule rule);

// The name an identifier gets when Mesa reserves it and browsers accept it (`packed` ->
// `toyhost_packed`); empty for every other word.
std::string_view webglOnlyIdentifierRename(std::string_view word);

}  // namespace toyhost
