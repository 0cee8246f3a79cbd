#include "shader/ShaderAssembly.h"

#include "shader/BrowserPreprocess.h"
#include "shader/GlslRewrite.h"
#include "shader/GlslTokens.h"
#include "shader/OpaqueDivisors.h"

#include <algorithm>
#include <cctype>
#include <vector>
#include <sstream>

namespace toyhost {

namespace {

const char* samplerKeyword(SamplerType type) {
    switch (type) {
        case SamplerType::SamplerCube: return "samplerCube";
        case SamplerType::Sampler3D: return "sampler3D";
        case SamplerType::Sampler2D: break;
    }
    return "sampler2D";
}

// True when `code` has a `#define NAME` directive (spaces allowed around the '#').
bool definesMacro(std::string_view code, std::string_view name) {
    std::size_t at = 0;
    while ((at = code.find("define", at)) != std::string_view::npos) {
        std::size_t hash = at;
        while (hash > 0 && (code[hash - 1] == ' ' || code[hash - 1] == '\t')) --hash;
        std::size_t after = at + 6;
        at = after;
        if (hash == 0 || code[hash - 1] != '#') continue;
        std::size_t start = hash - 1;
        while (start > 0 && (code[start - 1] == ' ' || code[start - 1] == '\t')) --start;
        if (start > 0 && code[start - 1] != '\n') continue;
        while (after < code.size() && (code[after] == ' ' || code[after] == '\t')) ++after;
        if (code.compare(after, name.size(), name) != 0) continue;
        const std::size_t end = after + name.size();
        if (end == code.size() || !(std::isalnum(static_cast<unsigned char>(code[end])) || code[end] == '_'))
            return true;
    }
    return false;
}

// The precision lines every pass starts with. Desktop GPUs, where shadertoys are written and
// checked, compute lowp and mediump in 32 bits; Mesa (llvmpipe included) lowers them to 16 bits,
// which breaks simulations that read float buffers through the default lowp sampler2D. The
// qualifiers are written highp by the source rewrite (not by macros: in WebGL `#ifdef lowp` is
// false), except where the user's code defines the same macro itself. Two empty lines keep the
// header's line numbers where the former macros were.
GlslRewriteOptions promotion(const ShaderInputs& in) {
    GlslRewriteOptions p;
    p.lowp = !(definesMacro(in.code, "lowp") || (in.common && definesMacro(*in.common, "lowp")));
    p.mediump = !(definesMacro(in.code, "mediump") || (in.common && definesMacro(*in.common, "mediump")));
    return p;
}

void writePrecision(std::ostringstream& h) {
    h << "#version 300 es\n"
         "#line " << kHeaderLineBase + 2 << "\n"
         "precision highp float;\n"
         "precision highp int;\n"
         "precision mediump sampler3D;\n"
         "precision highp sampler2D; precision highp samplerCube; precision highp sampler3D;\n"
         "\n\n";
}

void writeChannels(std::ostringstream& h, const ShaderInputs& in, bool structs) {
    for (int i = 0; i < kChannelCount; ++i) {
        const char* sampler = samplerKeyword(in.samplers[i]);
        h << "uniform " << sampler << " iChannel" << i << ";\n";
        if (structs)  // the newer per-channel struct API exists only in the Image pass
            h << "uniform struct {\n  " << sampler
              << " sampler;\n  vec3  size;\n  float time;\n  int   loaded;\n}iCh" << i << ";\n";
    }
}

// The Sound pass: mainSound(sample, time) for 512x512 samples per draw, each stereo sample
// written as two 16-bit values in the four bytes of an RGBA8 pixel.
std::string makeSoundHeader(const ShaderInputs& in) {
    std::ostringstream h;
    writePrecision(h);
    h << "#define HW_PERFORMANCE 1\n"
         "uniform float     iChannelTime[4];\n"
         "uniform float     iTimeOffset;\n"
         "uniform int       iSampleOffset;\n"
         "uniform vec4      iDate;\n"
         "uniform float     iSampleRate;\n"
         "uniform vec3      iChannelResolution[4];\n";
    writeChannels(h, in, false);
    h << "vec2 mainSound( in int samp, float time );\n"
         "\nout vec4 outColor;\n"
         "void main(){"
         "float t = iTimeOffset + ((gl_FragCoord.x-0.5) + (gl_FragCoord.y-0.5)*512.0)/iSampleRate;"
         "int   s = iSampleOffset + int(gl_FragCoord.y-0.2)*512 + int(gl_FragCoord.x-0.2);"
         "vec2 y = mainSound( s, t );"
         "vec2 v  = floor((0.5+0.5*y)*65536.0);"
         "vec2 vl = mod(v,256.0)/255.0;"
         "vec2 vh = floor(v/256.0)/255.0;"
         "outColor = vec4(vl.x,vh.x,vl.y,vh.y);}\n";
    return h.str();
}

// The header shadertoy.com's player (WebGL2) prepends to a pass, in its order.
std::string makeHeader(const ShaderInputs& in) {
    if (in.sound) return makeSoundHeader(in);
    const bool image = in.pass == PassId::Image;
    const bool cube = in.pass == PassId::CubeA;
    std::ostringstream h;
    writePrecision(h);
    h << "#define HW_PERFORMANCE 1\n"
         "uniform vec3      iResolution;\n"
         "uniform float     iTime;\n"
         "uniform float     iChannelTime[4];\n"
         "uniform vec4      iMouse;\n"
         "uniform vec4      iDate;\n"
         "uniform float     iSampleRate;\n"
         "uniform vec3      iChannelResolution[4];\n"
         "uniform int       iFrame;\n"
         "uniform float     iTimeDelta;\n"
         "uniform float     iFrameRate;\n";
    writeChannels(h, in, image);
    if (cube) {
        // Cube A: each face is drawn with its viewport and the four corner directions of the
        // face (unCorners[0..3]) around the apex unCorners[4]; mainCubemap gets the face pixel
        // and the ray through it.
        h << "uniform vec4      unViewport;\n"
             "uniform vec3      unCorners[5];\n"
             "void mainCubemap( out vec4 fragColor, in vec2 fragCoord, in vec3 fragRayOri, in vec3 fragRayDir );\n"
             "\nout vec4 outColor;\n"
             "void main( void ){"
             "vec4 color = vec4(0.0,0.0,0.0,1.0);"
             "vec3 ro = unCorners[4];"
             "vec2 uv = (gl_FragCoord.xy - unViewport.xy)/unViewport.zw;"
             "vec3 rd = normalize( mix( mix( unCorners[0], unCorners[1], uv.x ),"
             " mix( unCorners[3], unCorners[2], uv.x ), uv.y ) - ro);"
             "mainCubemap(color, gl_FragCoord.xy-unViewport.xy, ro, rd);"
             "outColor = color; }\n";
        return h.str();
    }
    h << "void mainImage( out vec4 c, in vec2 f );\n";
    if (image) {
        h << "void st_assert( bool cond );\n"
             "void st_assert( bool cond, int v );\n"
             "\nout vec4 shadertoy_out_color;\n"
             "void st_assert( bool cond, int v ) {if(!cond){if(v==0)shadertoy_out_color.x=-1.0;"
             "else if(v==1)shadertoy_out_color.y=-1.0;else if(v==2)shadertoy_out_color.z=-1.0;"
             "else shadertoy_out_color.w=-1.0;}}\n"
             "void st_assert( bool cond        ) {if(!cond)shadertoy_out_color.x=-1.0;}\n"
             "uniform vec2 " << kFragOffsetUniform << ";\n"
             "vec4 " << kFragCoordCopy << ";\n"
             "void main( void ){"
             << kFragCoordCopy << " = gl_FragCoord + vec4(" << kFragOffsetUniform << ", 0.0, 0.0);"
             "shadertoy_out_color = vec4(1.0,1.0,1.0,1.0);"
             "vec4 color = vec4(0.0,0.0,0.0,1.0);"
             "mainImage( color, " << kFragCoordCopy << ".xy );"
             "if(shadertoy_out_color.x<0.0) color=vec4(1.0,0.0,0.0,1.0);"
             "if(shadertoy_out_color.y<0.0) color=vec4(0.0,1.0,0.0,1.0);"
             "if(shadertoy_out_color.z<0.0) color=vec4(0.0,0.0,1.0,1.0);"
             "if(shadertoy_out_color.w<0.0) color=vec4(1.0,1.0,0.0,1.0);"
             "shadertoy_out_color = vec4(color.xyz,1.0);}\n";
    } else {
        // Buffers keep the alpha mainImage wrote.
        h << "\nout vec4 outColor;\n"
             "\nvoid main( void )\n"
             "{vec4 color = vec4(0.0,0.0,0.0,1.0);mainImage( color, gl_FragCoord.xy );"
             "outColor = color; }\n";
    }
    return h.str();
}

// Mesa 22 still offers GLSL ES 1.00's texture2D to 3.00 shaders; the site (WebGL2) refuses it.
// A global of that name, after the header, hides Mesa's function, so a call gets Mesa's own "no
// function with name 'texture2D'" (the site's verdict; webref probe cp_texture2D). Not when the
// user's text names it itself: a macro (`#define texture2D texture`), a function or a variable.
std::string hideTexture2D(std::string_view user) {
    const std::vector<GlslToken> tokens = tokenizeGlsl(user);
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        if (tokens[i].text != "texture2D") continue;
        const GlslToken& before = tokens[i - 1];
        if (tokens[i].directive ? before.text == "define" || before.text == "undef"
                                : before.kind == GlslToken::Kind::Identifier && before.text != "return" && before.text != "else")
            return {};
    }
    return "const int texture2D = 0;\n";
}

// Mesa lowers asin and acos to a polynomial that is off by up to 4e-4 rad (asin(0.9): 1.12012
// for 1.11977); browsers give them to a few float steps (ANGLE on SwiftShader, and the GPUs' own
// instructions under D3D11 and Metal). Through Mesa's atan, which agrees with SwiftShader's, the
// error is about 1e-6 (webref probe asin_acos, docs/shadertoy-behaviour.md). The rewrite calls
// these for every asin and acos of the user's text; only written when the text names either.
std::string preciseInverseTrigFunctions(std::string_view user) {
    bool named = false;
    for (const GlslToken& t : tokenizeGlsl(user))
        if (t.kind == GlslToken::Kind::Identifier && (t.text == "asin" || t.text == "acos")) named = true;
    if (!named) return {};
    std::string out;
    for (const char* type : {"float", "vec2", "vec3", "vec4"}) {
        out.append(type).append(" toyhost_asin(").append(type).append(" x) { return atan(x, sqrt((1.0 - x) * (1.0 + x))); }\n");
        out.append(type).append(" toyhost_acos(").append(type).append(" x) { return atan(sqrt((1.0 - x) * (1.0 + x)), x); }\n");
    }
    return out;
}

}  // namespace

AssembledShader assembleFragmentShader(const ShaderInputs& inputs) {
    AssembledShader out;
    const std::string headerStart = makeHeader(inputs) + macroDefineLines(inputs.defines);
    std::string user;
    if (inputs.common) {
        // Common is pasted followed by a newline.
        out.hasCommon = true;
        user += "#line " + std::to_string(kCommonLineBase + 1) + "\n";
        user += *inputs.common;
        user += '\n';
    }
    user += "#line 1\n";
    user += inputs.code;
    user = neutraliseUnknownDirectives(user);
    // WebGL zero-initialises locals at every declaration and `out` parameters at every call;
    // the rewrite (of the user's text, Common and pass together) keeps every line where it was.
    // The text without it is kept for a driver that refuses the rewritten one (a declaration the
    // rewrite misread).
    const std::string header = headerStart + hideTexture2D(user) + preciseInverseTrigFunctions(user) +
                               opaqueDivisorDeclarations(user);
    GlslRewriteOptions options = promotion(inputs);
    if (inputs.pass == PassId::Image && !inputs.sound) options.fragCoord = kFragCoordCopy;
    out.parts = {header, std::move(user), options};
    out.text = rewrittenShader(out.parts, options);
    for (RewriteRule rule : kRewriteRules) ruleSwitch(options, rule) = false;
    out.plainText = rewrittenShader(out.parts, options);
    return out;
}

std::string rewrittenShader(const RewriteParts& parts, const GlslRewriteOptions& options) {
    return parts.header + rewriteLikeWebGL(parts.user, options);
}

const char* fullscreenVertexShader() {
    return "#version 300 es\n"
           "void main() {\n"
           "    vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1));\n"
           "    gl_Position = vec4(corner - 1.0, 0.0, 1.0);\n"
           "}\n";
}

SourceLine mapGeneratedLine(int line) {
    if (line > kHeaderLineBase) return {SourceLine::Part::Header, line - kHeaderLineBase};
    if (line > kCommonLineBase) return {SourceLine::Part::Common, line - kCommonLineBase};
    return {SourceLine::Part::Pass, line};
}

}  // namespace toyhost
