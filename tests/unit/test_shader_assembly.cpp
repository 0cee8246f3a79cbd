// ShaderAssembly and CompilerLog: the generated header (content and order per SEMANTICS.md),
// Common pasting, the #line numbering that maps compiler messages back to the user's files (also
// with the user's own #line), and compiler-log parsing for Mesa, ANGLE and NVIDIA.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "shader/CompilerLog.h"
#include "shader/ShaderAssembly.h"

using namespace toyhost;

namespace {

const std::string kPassCode =
    "// line 1\n"
    "float f(float x) { return x * 2.0; }\n"
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "    fragColor = vec4(f(fragCoord.x), 0.0, 0.0, 0.5);\n"
    "}\n";

AssembledShader assemble(PassId pass, const std::string* common = nullptr, std::string_view code = kPassCode,
                         std::array<SamplerType, kChannelCount> samplers = {}) {
    ShaderInputs in;
    in.pass = pass;
    in.common = common;
    in.code = code;
    in.samplers = samplers;
    return assembleFragmentShader(in);
}

// Splits on '\n'; a trailing newline does not make an extra empty line.
std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        lines.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// The generated header: everything before the #line that starts Common or the pass code.
std::string headerOf(const AssembledShader& s) {
    std::string header;
    const std::string common = "#line " + std::to_string(kCommonLineBase + 1);
    for (const std::string& line : splitLines(s.text)) {
        if (line == common || line == "#line 1") break;
        header += line + "\n";
    }
    return header;
}

// The line number a GLSL ES 3.00 preprocessor gives each physical line of `text` (1-based, in
// order): counting from 1, and after "#line N" the next line is N (checked on Mesa).
std::vector<int> reportedLines(const std::string& text) {
    std::vector<int> numbers;
    int next = 1;
    static const std::regex directive(R"(^\s*#\s*line\s+(\d+).*$)");
    for (const std::string& line : splitLines(text)) {
        numbers.push_back(next);
        std::smatch m;
        next = std::regex_match(line, m, directive) ? std::stoi(m[1]) : next + 1;
    }
    return numbers;
}

// Offset of the first match of `pattern` in `text`, or npos.
size_t findRegex(const std::string& text, const std::string& pattern) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(pattern))) return std::string::npos;
    return static_cast<size_t>(m.position(0));
}

int countMatches(const std::string& text, const std::string& pattern) {
    const std::regex re(pattern);
    return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

// The line number the compiler reports for the first occurrence of `token`.
int reportedLineOf(const AssembledShader& s, const std::string& token) {
    const size_t at = s.text.find(token);
    EXPECT_NE(at, std::string::npos) << token;
    const size_t physical = static_cast<size_t>(std::count(s.text.begin(), s.text.begin() + static_cast<long>(at), '\n'));
    return reportedLines(s.text).at(physical);
}

const char* partName(SourceLine::Part p) {
    switch (p) {
        case SourceLine::Part::Header: return "Header";
        case SourceLine::Part::Common: return "Common";
        case SourceLine::Part::Pass: return "Pass";
    }
    return "?";
}

}  // namespace

// ---- Header --------------------------------------------------------------------------------------

TEST(ShaderAssembly, HeaderStartsWithVersionThenPrecisionThenHwPerformance) {
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        const AssembledShader s = assemble(pass);
        const std::vector<std::string> lines = splitLines(s.text);
        ASSERT_FALSE(lines.empty());
        EXPECT_EQ(lines[0], "#version 300 es");
        const std::string header = headerOf(s);
        const size_t hw = header.find("\n#define HW_PERFORMANCE 1\n");
        ASSERT_NE(hw, std::string::npos) << header;
        for (const char* precision : {"precision highp float;", "precision highp int;", "precision mediump sampler3D;"}) {
            const size_t at = header.find(precision);
            EXPECT_NE(at, std::string::npos) << precision;
            EXPECT_LT(at, hw) << precision << " must come before HW_PERFORMANCE";
        }
        EXPECT_EQ(countMatches(header, "#version"), 1);
        EXPECT_EQ(countMatches(header, "HW_PERFORMANCE"), 1);
        // Nothing but preprocessor and precision statements before the uniforms.
        EXPECT_LT(hw, header.find("uniform"));
    }
}

TEST(ShaderAssembly, UniformsInDocumentedOrder) {
    const char* uniforms[][2] = {{"vec3", "iResolution"},        {"float", "iTime"},
                                 {"float", "iChannelTime\\[4\\]"}, {"vec4", "iMouse"},
                                 {"vec4", "iDate"},                {"float", "iSampleRate"},
                                 {"vec3", "iChannelResolution\\[4\\]"}, {"int", "iFrame"},
                                 {"float", "iTimeDelta"},          {"float", "iFrameRate"},
                                 {"sampler2D", "iChannel0"},       {"sampler2D", "iChannel1"},
                                 {"sampler2D", "iChannel2"},       {"sampler2D", "iChannel3"}};
    for (PassId pass : {PassId::Image, PassId::BufferC}) {
        const std::string header = headerOf(assemble(pass));
        const size_t hw = header.find("#define HW_PERFORMANCE 1");
        size_t previous = hw;
        for (const auto& [type, name] : uniforms) {
            const std::string pattern = std::string("\\n\\s*uniform\\s+") + type + "\\s+" + name + "\\s*;";
            const size_t at = findRegex(header, pattern);
            ASSERT_NE(at, std::string::npos) << passName(pass) << ": no " << type << " " << name;
            EXPECT_GT(at, previous) << passName(pass) << ": " << name << " out of order";
            EXPECT_EQ(countMatches(header, pattern), 1) << name;
            previous = at;
        }
        // Exactly these plain uniforms (plus the iCh structs in the Image pass).
        EXPECT_EQ(countMatches(header, "\\buniform\\s+(vec3|vec4|float|int|sampler2D|samplerCube|sampler3D)\\s"), 14);
    }
}

TEST(ShaderAssembly, ChannelStructsAndStAssertOnlyInImage) {
    const std::string image = headerOf(assemble(PassId::Image));
    for (int i = 0; i < 4; ++i) {
        const std::string pattern = "uniform\\s+struct\\s*\\{\\s*sampler2D\\s+sampler\\s*;\\s*vec3\\s+size\\s*;\\s*"
                                    "float\\s+time\\s*;\\s*int\\s+loaded\\s*;\\s*\\}\\s*iCh" +
                                    std::to_string(i) + "\\s*;";
        EXPECT_EQ(countMatches(image, pattern), 1) << "iCh" << i << " in\n" << image;
    }
    EXPECT_EQ(countMatches(image, "\\biCh[0-9]\\b"), 4);
    EXPECT_GE(countMatches(image, "void\\s+st_assert\\s*\\(\\s*bool\\s+\\w+\\s*\\)"), 1);
    EXPECT_GE(countMatches(image, "void\\s+st_assert\\s*\\(\\s*bool\\s+\\w+\\s*,\\s*int\\s+\\w+\\s*\\)"), 1);

    for (PassId buffer : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD}) {
        const std::string header = headerOf(assemble(buffer));
        EXPECT_EQ(countMatches(header, "\\biCh[0-9]\\b"), 0) << passName(buffer);
        EXPECT_EQ(header.find("struct"), std::string::npos) << passName(buffer);
        EXPECT_EQ(header.find("st_assert"), std::string::npos) << passName(buffer);
    }
}

TEST(ShaderAssembly, MainWrapperImageForcesAlphaBuffersKeepIt) {
    for (PassId pass : {PassId::Image, PassId::BufferA, PassId::BufferD}) {
        const std::string header = headerOf(assemble(pass));
        // The forward declaration comes before main().
        const size_t declaration =
            findRegex(header, "void\\s+mainImage\\s*\\(\\s*out\\s+vec4\\s+\\w+\\s*,\\s*in\\s+vec2\\s+\\w+\\s*\\)\\s*;");
        const size_t main = findRegex(header, "void\\s+main\\s*\\(\\s*void\\s*\\)");
        ASSERT_NE(declaration, std::string::npos) << passName(pass);
        ASSERT_NE(main, std::string::npos) << passName(pass);
        EXPECT_LT(declaration, main);
        EXPECT_EQ(countMatches(header, "\\bout\\s+vec4\\s+\\w+\\s*;"), 1) << passName(pass) << ": one output";

        const std::string body = header.substr(main);
        const size_t init = body.find("vec4 color = vec4(0.0,0.0,0.0,1.0);");
        // Image: fragCoord is gl_FragCoord moved by the sample's or tile's offset (zero: the site's).
        const size_t call = body.find(pass == PassId::Image ? "mainImage( color, toyhost_FragCoord.xy );"
                                                            : "mainImage( color, gl_FragCoord.xy );");
        if (pass == PassId::Image) {
            const size_t copy = body.find("toyhost_FragCoord = gl_FragCoord + vec4(toyhost_fragOffset, 0.0, 0.0);");
            ASSERT_NE(copy, std::string::npos);
            EXPECT_LT(copy, call);
        }
        ASSERT_NE(init, std::string::npos) << passName(pass);
        ASSERT_NE(call, std::string::npos) << passName(pass);
        EXPECT_LT(init, call);
        if (pass == PassId::Image) {
            const size_t write = body.find("shadertoy_out_color = vec4(color.xyz,1.0);");
            ASSERT_NE(write, std::string::npos);
            EXPECT_LT(call, write);
            EXPECT_NE(header.find("out vec4 shadertoy_out_color;"), std::string::npos);
        } else {
            const size_t write = body.find("outColor = color;");
            ASSERT_NE(write, std::string::npos) << passName(pass);
            EXPECT_LT(call, write);
            EXPECT_EQ(body.find("color.xyz"), std::string::npos) << passName(pass) << " must keep alpha";
            EXPECT_NE(header.find("out vec4 outColor;"), std::string::npos);
        }
    }
}

TEST(ShaderAssembly, SamplerKeywordsPerChannel) {
    const std::array<SamplerType, 4> samplers{SamplerType::SamplerCube, SamplerType::Sampler2D, SamplerType::Sampler3D,
                                              SamplerType::SamplerCube};
    const char* expected[] = {"samplerCube", "sampler2D", "sampler3D", "samplerCube"};
    for (PassId pass : {PassId::Image, PassId::BufferB}) {
        const std::string header = headerOf(assemble(pass, nullptr, kPassCode, samplers));
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(countMatches(header, "\\buniform\\s+" + std::string(expected[i]) + "\\s+iChannel" +
                                               std::to_string(i) + "\\s*;"),
                      1)
                << passName(pass) << " iChannel" << i;
            if (pass == PassId::Image) {
                EXPECT_EQ(countMatches(header, "struct\\s*\\{\\s*" + std::string(expected[i]) +
                                                   "\\s+sampler\\s*;[^}]*\\}\\s*iCh" + std::to_string(i) + "\\s*;"),
                          1)
                    << "iCh" << i << " sampler type";
            }
        }
    }
}

// ---- Common and pass code ------------------------------------------------------------------------

TEST(ShaderAssembly, TextIsHeaderThenCommonAndNewlineThenPassCode) {
    const std::string common = "#define TAU 6.2831853\nfloat sq(float x) { return x * x; }";
    // mainImage's `out` is zero-initialised on the line of its brace, as WebGL's translator does.
    std::string passCode = kPassCode;
    passCode.replace(passCode.find("fragCoord) {") + 12, 0, "fragColor=vec4(0);");
    const std::string commonLine = "#line " + std::to_string(kCommonLineBase + 1) + "\n";
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        const AssembledShader without = assemble(pass);
        const std::string header = headerOf(without);
        EXPECT_EQ(without.text, header + "#line 1\n" + passCode);
        EXPECT_FALSE(without.hasCommon);

        const AssembledShader with = assemble(pass, &common);
        EXPECT_EQ(with.text, header + commonLine + common + "\n#line 1\n" + passCode);
        EXPECT_TRUE(with.hasCommon);

        const std::string commonWithNewline = common + "\n";
        EXPECT_EQ(assemble(pass, &commonWithNewline).text, header + commonLine + commonWithNewline + "\n#line 1\n" + passCode);

        const std::string empty;
        EXPECT_EQ(assemble(pass, &empty).text, header + commonLine + "\n#line 1\n" + passCode);
    }
}

TEST(ShaderAssembly, FullscreenVertexShaderIsGlslEs300) {
    const std::string vs = fullscreenVertexShader();
    EXPECT_EQ(vs.rfind("#version 300 es\n", 0), 0u);
    EXPECT_NE(vs.find("gl_VertexID"), std::string::npos);
    EXPECT_NE(vs.find("gl_Position"), std::string::npos);
}

// ---- Line mapping --------------------------------------------------------------------------------

TEST(ShaderAssembly, MapReportedLineBands) {
    EXPECT_EQ(mapGeneratedLine(1).part, SourceLine::Part::Pass);
    EXPECT_EQ(mapGeneratedLine(1).line, 1);
    EXPECT_EQ(mapGeneratedLine(kCommonLineBase).part, SourceLine::Part::Pass);
    EXPECT_EQ(mapGeneratedLine(kCommonLineBase + 1).part, SourceLine::Part::Common);
    EXPECT_EQ(mapGeneratedLine(kCommonLineBase + 1).line, 1);
    EXPECT_EQ(mapGeneratedLine(kHeaderLineBase + 3).part, SourceLine::Part::Header);
    EXPECT_EQ(mapGeneratedLine(kHeaderLineBase + 3).line, 3);
}

// Marker tokens on known lines: wherever they land in the assembled text, the number the compiler
// reports for them must lead back to their line, for every way Common can end, with CRLF line
// endings, and with the user's own #line in the pass.
TEST(ShaderAssembly, MappingIsRightByConstruction) {
    std::string pass;
    for (int line = 1; line <= 40; ++line) pass += "// pass line " + std::to_string(line) + " PASS_MARK_" + std::to_string(line) + "_\n";
    std::string passNoFinalNewline = pass.substr(0, pass.size() - 1);
    std::string passCrlf;
    for (int line = 1; line <= 40; ++line) passCrlf += "PASS_MARK_" + std::to_string(line) + "_ x\r\n";

    std::string common;
    for (int line = 1; line <= 7; ++line) common += "COMMON_MARK_" + std::to_string(line) + "_\n";
    const std::string commonNoFinalNewline = common.substr(0, common.size() - 1);

    const std::string* commons[] = {nullptr, &common, &commonNoFinalNewline};
    const std::string* passes[] = {&pass, &passNoFinalNewline, &passCrlf};
    for (PassId id : {PassId::Image, PassId::BufferB}) {
        for (const std::string* c : commons) {
            for (const std::string* p : passes) {
                const AssembledShader s = assemble(id, c, *p);
                for (int line = 1; line <= 40; ++line) {
                    const SourceLine got = mapGeneratedLine(reportedLineOf(s, "PASS_MARK_" + std::to_string(line) + "_"));
                    EXPECT_EQ(got.part, SourceLine::Part::Pass);
                    EXPECT_EQ(got.line, line) << "pass marker, common " << (c ? "yes" : "no");
                }
                if (!c) continue;
                for (int line = 1; line <= 7; ++line) {
                    const SourceLine got = mapGeneratedLine(reportedLineOf(s, "COMMON_MARK_" + std::to_string(line) + "_"));
                    EXPECT_EQ(got.part, SourceLine::Part::Common);
                    EXPECT_EQ(got.line, line) << "common marker";
                }
                // Every line of Common and the pass maps to a line whose text is that line's text;
                // header lines map into the header.
                const std::vector<std::string> generated = splitLines(s.text);
                const std::vector<int> reported = reportedLines(s.text);
                const std::vector<std::string> passLines = splitLines(*p);
                const std::vector<std::string> commonLines = c ? splitLines(*c) : std::vector<std::string>{};
                // Line 1 is "#version 300 es", which must come before anything else (so before any
                // #line); it is toyhost's own and no user code can make a message point at it.
                ASSERT_EQ(generated[0], "#version 300 es");
                for (size_t g = 1; g < generated.size(); ++g) {
                    if (generated[g].rfind("#line ", 0) == 0) continue;
                    const SourceLine where = mapGeneratedLine(reported[g]);
                    if (where.part == SourceLine::Part::Header) {
                        EXPECT_LT(g, splitLines(headerOf(s)).size()) << "line " << g << " is not in the header";
                        continue;
                    }
                    const std::vector<std::string>& source = where.part == SourceLine::Part::Common ? commonLines : passLines;
                    const std::string expected =
                        where.line <= static_cast<int>(source.size()) ? source[where.line - 1] : std::string();
                    EXPECT_EQ(generated[g], expected) << "generated line " << g + 1 << " -> " << partName(where.part) << " "
                                                      << where.line;
                }
            }
        }
    }
}

TEST(ShaderAssembly, AUsersOwnLineDirectiveNeverPointsIntoTheHeader) {
    const std::string common = "float c;\n";
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n#line 5\n  MARK_AFTER_5\n#line 40\n  MARK_AFTER_40\n}\n";
    const AssembledShader s = assemble(PassId::Image, &common, code);
    for (auto [token, line] : {std::pair<const char*, int>{"MARK_AFTER_5", 5}, {"MARK_AFTER_40", 40}}) {
        const SourceLine got = mapGeneratedLine(reportedLineOf(s, token));
        EXPECT_EQ(got.part, SourceLine::Part::Pass) << token;
        EXPECT_EQ(got.line, line) << token;
    }
}

// ---- Compiler logs -------------------------------------------------------------------------------

namespace {
const CompilerLogNames kNames{"Image", "/toys/image.glsl", "/toys/common.glsl"};

std::string parsed(const std::string& log) {
    std::string out;
    for (const Diagnostic& d : parseCompilerLog(log, kNames)) out += (out.empty() ? "" : "\n") + formatDiagnostic(d);
    return out;
}
std::string common(int line) { return std::to_string(kCommonLineBase + line); }
std::string header(int line) { return std::to_string(kHeaderLineBase + line); }
}  // namespace

TEST(ShaderAssembly, ParseMesaLog) {
    const std::string log = "0:4(12): error: `foo' undeclared\n0:" + common(2) + "(7): warning: unused variable\n0:" +
                            header(3) + "(1): error: something in the header\n";
    EXPECT_EQ(parsed(log),
              "/toys/image.glsl:4:12: error: Image: `foo' undeclared [shader.compile]\n"
              "/toys/common.glsl:2:7: warning: Image: unused variable [shader.compile]\n"
              "<toyhost header>:3:1: error: Image: something in the header [shader.compile]");
    const std::vector<Diagnostic> d = parseCompilerLog("0:4(12): error: `foo' undeclared", kNames);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].file, "/toys/image.glsl");
    EXPECT_EQ(d[0].pass, "Image");
    EXPECT_EQ(d[0].line, 4);
    EXPECT_EQ(d[0].column, 12);
    EXPECT_EQ(d[0].severity, Severity::Error);
    EXPECT_EQ(d[0].message, "`foo' undeclared");
}

TEST(ShaderAssembly, ParseAngleLog) {
    const std::string log = "ERROR: 0:2: 'foo' : undeclared identifier\nWARNING: 0:" + common(3) +
                            ": 'bar' : unused\nERROR: 2 compilation errors.  No code generated.\n";
    EXPECT_EQ(parsed(log),
              "/toys/image.glsl:2: error: Image: 'foo' : undeclared identifier [shader.compile]\n"
              "/toys/common.glsl:3: warning: Image: 'bar' : unused [shader.compile]\n"
              "/toys/image.glsl: error: Image: ERROR: 2 compilation errors.  No code generated. [shader.compile]");
}

TEST(ShaderAssembly, ParseNvidiaLog) {
    const std::string log = "0(5) : error C1008: undefined variable \"foo\"\n0(" + common(1) +
                            ") : warning C7022: unrecognized profile specifier\n";
    EXPECT_EQ(parsed(log),
              "/toys/image.glsl:5: error: Image: undefined variable \"foo\" [shader.compile]\n"
              "/toys/common.glsl:1: warning: Image: unrecognized profile specifier [shader.compile]");
}

TEST(ShaderAssembly, ParseKeepsLinesWithoutLocationAndHandlesCrlf) {
    const std::string log = "Compilation failed.\r\n\r\n0:1(3): error: syntax error, unexpected IDENTIFIER\r\nlink: not attempted";
    EXPECT_EQ(parsed(log),
              "/toys/image.glsl: error: Image: Compilation failed. [shader.compile]\n"
              "/toys/image.glsl:1:3: error: Image: syntax error, unexpected IDENTIFIER [shader.compile]\n"
              "/toys/image.glsl: error: Image: link: not attempted [shader.compile]");
    EXPECT_EQ(parsed(""), "");
}

// The Image pass reads the moved copy wherever its code (and Common in it) says gl_FragCoord, in
// #define bodies too; the other passes keep gl_FragCoord.
TEST(ShaderAssembly, OnlyTheImagePassReadsTheMovedFragCoordCopy) {
    const std::string common = "#define PIXEL gl_FragCoord.xy\nvec2 at() { return gl_FragCoord.xy; }\n";
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        ShaderInputs in;
        in.pass = pass;
        in.common = &common;
        in.code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(gl_FragCoord.xy + PIXEL + at(), 0, 1); }\n";
        const AssembledShader shader = assembleFragmentShader(in);
        for (const std::string* text : {&shader.text, &shader.plainText}) {
            const std::string user = text->substr(text->find("#line 1000001"));
            EXPECT_EQ(user.find("gl_FragCoord") == std::string::npos, pass == PassId::Image) << *text;
            EXPECT_EQ(countMatches(user, "toyhost_FragCoord"), pass == PassId::Image ? 3 : 0) << *text;
        }
    }
}

// The precise asin/acos (every overload) are in the header only when the user's text names them,
// and the plain text (the fallback) calls the driver's own.
TEST(ShaderAssembly, PreciseInverseTrigOnlyWhenNamed) {
    const AssembledShader plain = assemble(PassId::Image);
    EXPECT_EQ(plain.text.find("toyhost_asin"), std::string::npos);
    const std::string code = "void mainImage(out vec4 o, in vec2 f) { o = vec4(asin(f.x), acos(f), 0.0); }\n";
    const AssembledShader named = assemble(PassId::Image, nullptr, code);
    for (const char* type : {"float", "vec2", "vec3", "vec4"}) {
        EXPECT_NE(named.text.find(std::string(type) + " toyhost_asin(" + type + " x)"), std::string::npos) << type;
        EXPECT_NE(named.text.find(std::string(type) + " toyhost_acos(" + type + " x)"), std::string::npos) << type;
    }
    EXPECT_NE(named.text.find("o = vec4(toyhost_asin(f.x), toyhost_acos(f), 0.0);"), std::string::npos);
    EXPECT_NE(named.plainText.find("o = vec4(asin(f.x), acos(f), 0.0);"), std::string::npos);
}
