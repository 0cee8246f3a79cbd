// The catalogue of bad inputs: every way a user can hand toyhost something wrong (options, manifests,
// exports, input scripts, shaders, output places, a full disk, a shader that never finishes), each
// run through the CLI as a user runs it, asserting
//   - the exact exit code (2 usage, 1 the run failed, 124 the watchdog),
//   - exactly one line with "error:" (or the stated number, for a case about reporting several
//     problems at once), each in the one form "toyhost: ...",
//   - the place in that message (file, JSON field, pass, FILE:LINE:COL, option) and the short code,
//   - no file left behind: nothing new anywhere in the case's folder (the output folder included,
//     hidden .partial files included, ffmpeg's log in $TMPDIR included), except empty folders.
// No case skips on failure: a case that meets a known defect fails. Should one be kept in the
// catalogue before its fix, it gets its own CTest entry with WILL_FAIL (an add_test running this
// executable with --gtest_filter for it, and the case left out of gtest_discover_tests with
// TEST_FILTER), so that it fails until fixed and its fix shows as a failure to remove the mark.
#include "GlTestSupport.h"
#include "UniformPng.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

// What the case's folder needs besides files.
enum class Mount {
    None,
    Full,      // a 100 KiB tmpfs on <dir>/out: the disk fills up
    ReadOnly,  // a read-only tmpfs on <dir>/out (or chmod 555 when mounting is not allowed and not root)
};

struct Case {
    std::string name;  // the test's name
    // Files to create, relative to the case's folder ("@D" in paths and contents is that folder).
    // Contents "<folder>", "<fifo>" and "<link:TARGET>" make a folder, a FIFO and a symbolic link.
    std::vector<std::pair<std::string, std::string>> files;
    std::string args;                   // toyhost's arguments, shell-quoted, "@D" for the folder
    int exit = 1;                       // the exact exit code
    std::vector<std::string> mentions;  // the message holds each ("~text": case-insensitively)
    std::string code;                   // the short code in brackets; empty: not checked
    int errors = 1;                     // lines with "error:"
    Mount mount = Mount::None;
    std::string env;        // extra VAR=value settings for toyhost
    std::string prepare;    // a toyhost run before the case (must succeed), e.g. making a checkpoint
    bool needsFfmpeg = false;
    long long fileSizeLimit = 0;  // bytes: toyhost runs under `ulimit -f` (prlimit --fsize)
};

// ---- building the table -----------------------------------------------------------------------

const std::string kImage = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n";
const std::string kManifest = R"({"passes": {"Image": {"source": "image.glsl"}}})";
const std::string kGrayNoise = "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png";
const std::string kGrayNoiseTypo = "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f6.png";

// A shader whose frame runs for minutes on llvmpipe (each loop is capped near 65535 iterations,
// hence two nested loops with a heavy body).
const std::string kEndlessFrame = R"(void mainImage(out vec4 c, in vec2 p) {
    float x = p.x / iResolution.x, s = 0.0;
    for (int j = 0; j < 1000; j++) {
        for (int i = 0; i < int(iResolution.x) * 200; i++) {
            s += sin(x * 1.0 + s); s += sin(x * 2.0 + s); s += sin(x * 3.0 + s); s += sin(x * 4.0 + s);
            s += sin(x * 5.0 + s); s += sin(x * 6.0 + s); s += sin(x * 7.0 + s); s += sin(x * 8.0 + s);
            s += sin(x * 9.0 + s); s += sin(x * 10.0 + s); s += sin(x * 11.0 + s); s += sin(x * 12.0 + s);
            s += sin(x * 13.0 + s); s += sin(x * 14.0 + s); s += sin(x * 15.0 + s); s += sin(x * 16.0 + s);
            s += sin(x * 17.0 + s); s += sin(x * 18.0 + s); s += sin(x * 19.0 + s); s += sin(x * 20.0 + s);
        }
    }
    c = vec4(s);
}
)";

// A shader of `statements` x 1000 statements (macros expand them): 3000 take seconds to compile
// on llvmpipe (with Mesa's shader cache off), 10000 overflow Mesa's compiler stack.
std::string bigShader(int thousands) {
    std::string body;
    for (int i = 0; i < thousands; ++i) body += " D";
    return "#define A s = sin(s * 1.1 + x);\n"
           "#define B A A A A A A A A A A\n"
           "#define C B B B B B B B B B B\n"
           "#define D C C C C C C C C C C\n"
           "void mainImage(out vec4 c, in vec2 p) {\n"
           "    float x = p.x, s = 0.0;\n"
           "   " + body + "\n"
           "    c = vec4(s);\n"
           "}\n";
}

// Incompressible frames (every pixel a hash), so that a 100 KiB disk fills on the first frame.
const std::string kNoise = R"(float hash(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233)) + iTime) * 43758.5453); }
void mainImage(out vec4 c, in vec2 p) {
    c = vec4(hash(p), hash(p + 1.0), hash(p + 2.0), 1.0);
}
)";

using Files = std::vector<std::pair<std::string, std::string>>;

// A grey JPEG declaring width x height whose data codes `codedBlocks` 8x8 blocks as tightly as
// Huffman coding can (1-bit codes for DC difference 0 and end of block), then `emptyScans` empty
// AC scans (progressive when there are any: each one makes libjpeg visit every block again).
std::string greyJpeg(int width, int height, std::size_t codedBlocks, int emptyScans = 0) {
    std::string b = "\xFF\xD8\xFF\xDB"s + '\0' + char(67) + '\0' + std::string(64, '\1');
    const char sof = emptyScans ? '\xC2' : '\xC0';
    b += "\xFF"s + sof + '\0' + char(11) + char(8) + char(height >> 8) + char(height & 255) + char(width >> 8) +
         char(width & 255) + char(1) + char(1) + char(0x11) + '\0';
    for (char table : {'\x00', '\x10'}) b += "\xFF\xC4"s + '\0' + char(20) + table + char(1) + std::string(16, '\0');
    const std::string dcScan = "\xFF\xDA"s + '\0' + char(8) + char(1) + char(1) + '\0' + '\0' + char(emptyScans ? 0 : 63) + '\0';
    b += dcScan + std::string(emptyScans ? (codedBlocks + 7) / 8 : (codedBlocks * 2 + 7) / 8, '\0');
    for (int i = 0; i < emptyScans; ++i) b += "\xFF\xDA"s + '\0' + char(8) + char(1) + char(1) + '\0' + char(1) + char(63) + '\0';
    return b + "\xFF\xD9";
}


// toy/manifest.json (the given text) and toy/image.glsl, then `extra` (which may replace them).
Files toy(const std::string& manifest = kManifest, Files extra = {}) {
    Files files{{"toy/manifest.json", manifest}, {"toy/image.glsl", kImage}};
    files.insert(files.end(), extra.begin(), extra.end());
    return files;
}

// A run of the toy, small and short, capturing PNGs into <dir>/out.
std::string runToy(const std::string& extra = "") {
    return "run '@D/toy' --size 16x8 --frames 2 --quiet --out '@D/out/f_%04d.png'" + (extra.empty() ? "" : " " + extra);
}

// A run of the toy with its own size, frames and output (no defaults that could clash).
std::string runToyBare(const std::string& options) { return "run '@D/toy' --quiet " + options; }

// Shadertoy exports in the API form.
std::string apiPass(const std::string& type, const std::string& name, const std::string& outputs, const std::string& code,
                    const std::string& inputs = "[]") {
    return R"({"inputs": )" + inputs + R"(, "outputs": )" + outputs + R"(, "code": )" + code + R"(, "name": ")" + name +
           R"(", "description": "", "type": ")" + type + R"("})";
}
std::string imagePass(const std::string& inputs = "[]") {
    return apiPass("image", "Image", R"([{"id": 37, "channel": 0}])",
                   R"("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n")", inputs);
}
std::string apiExport(const std::string& renderpass) {
    return R"({"Shader": {"ver": "0.1", "info": {"id": "tSt123", "name": "Synthetic", "username": "tester"}, "renderpass": )" +
           renderpass + "}}";
}
Files exportFile(const std::string& text) { return {{"export.json", text}}; }
std::string runExport() { return "run '@D/export.json' --size 16x8 --frames 2 --quiet --out '@D/out/f_%04d.png'"; }

std::string manifestWithChannel(const std::string& channel) {
    return R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": )" + channel + "}}}}";
}
std::string manifestWithBufferA(const std::string& imageChannel) {
    return R"({"passes": {"Buffer A": {"source": "image.glsl"}, "Image": {"source": "image.glsl", "channels": {"iChannel0": )" +
           imageChannel + "}}}}";
}

const std::string kManifestPath = "@D/toy/manifest.json";

std::vector<Case> catalogue() {
    std::vector<Case> cases;
    auto add = [&](Case c) { cases.push_back(std::move(c)); };
    auto usage = [&](const std::string& name, const std::string& options, std::vector<std::string> mentions,
                     const std::string& code = "usage") {
        add({name, toy(), runToyBare(options), 2, std::move(mentions), code});
    };
    const std::string small = "--size 16x8 --frames 2 --out '@D/out/f_%04d.png'";

    // ---- command-line usage: exit 2, the option named --------------------------------------------
    usage("FramesZero", "--size 16x8 --frames 0 --out '@D/out/f_%04d.png'", {"--frames"});
    usage("FramesNegative", "--size 16x8 --frames -1 --out '@D/out/f_%04d.png'", {"--frames"});
    usage("FramesNotANumber", "--size 16x8 --frames abc --out '@D/out/f_%04d.png'", {"--frames", "abc"});
    usage("FramesBeyondInt", "--size 16x8 --frames 99999999999 --out '@D/out/f_%04d.png'", {"--frames", "99999999999"});
    // Numbers are decimal digits (CLI11 alone reads 0x10 as 16, 010 as octal 8, '' as "not given").
    usage("FramesEmpty", "--size 16x8 --frames '' --out '@D/out/f_%04d.png'", {"--frames", "empty"});
    usage("FramesHex", "--size 16x8 --frames 0x10 --out '@D/out/f_%04d.png'", {"--frames", "\"0x10\"", "decimal"});
    usage("PngLevelLeadingZero", small + " --png-level 010", {"--png-level", "0..9"});
    // Once defects (issue 46): options outside the commands' own lists skipped the check
    // (--supersample 0x10 was 16, --tile 0x40 64), and --size wrapped at 2^32 (4294967396x100
    // rendered 100x100; 99999999999x1 was refused as 1215752191x1). Every numeric option of every
    // command is read one way now (tools/toyhost/NumberOptions.h), --size part by part.
    usage("SupersampleHex", small + " --supersample 0x10", {"--supersample", "\"0x10\"", "decimal"});
    usage("MotionBlurHex", small + " --motion-blur 0x10", {"--motion-blur", "\"0x10\"", "decimal"});
    usage("TileHex", small + " --tile 0x40", {"--tile", "\"0x40\"", "decimal"});
    usage("ShutterHexFloat", small + " --shutter 0x1p4 --motion-blur 2", {"--shutter", "\"0x1p4\""});
    usage("SizeBeyond32Bits", "--frames 2 --size 4294967396x100 --out '@D/out/f_%04d.png'",
          {"--size 4294967396x100", "\"4294967396\" is too large"});
    usage("SizeWidthBeyondInt", "--frames 2 --size 99999999999x1 --out '@D/out/f_%04d.png'",
          {"--size 99999999999x1", "\"99999999999\" is too large"});
    usage("SizeHexSide", "--frames 2 --size 16x0x10 --out '@D/out/f_%04d.png'", {"--size 16x0x10"});
    usage("FrameRangeBeyondInt", "--size 16x8 --frames 10 --out '@D/out/f_%04d.png' --frame-range 0:4294967297",
          {"--frame-range 0:4294967297", "too large"});
    usage("FpsHexFloat", small + " --fps 0x1p4", {"--fps", "\"0x1p4\""});
    usage("CompileTimeoutTiny", small + " --compile-timeout 1e-9", {"--compile-timeout", "0 (off) or from 0.1"});
    usage("FrameTimeoutTiny", small + " --frame-timeout 0.01", {"--frame-timeout", "0 (off) or from 0.1"});
    usage("FpsZero", small + " --fps 0", {"--fps"});
    usage("FpsNan", small + " --fps nan", {"--fps"});
    usage("FpsInfinite", small + " --fps inf", {"--fps"});
    usage("FpsTiny", small + " --fps 1e-300", {"--fps"});
    // Once a defect: the range message did not name the option --size.
    usage("SizeZero", "--frames 2 --size 0x0 --out '@D/out/f_%04d.png'", {"--size", "0x0"}, "usage.size");
    usage("SizeHuge", "--frames 2 --size 99999x99999 --out '@D/out/f_%04d.png'", {"--size", "99999x99999"}, "usage.size");
    usage("SizeNotWxH", "--frames 2 --size abc --out '@D/out/f_%04d.png'", {"--size abc", "WxH"});
    usage("SizeTrailingJunk", "--frames 2 --size 16x8x --out '@D/out/f_%04d.png'", {"--size 16x8x"});
    usage("PngLevelTen", small + " --png-level 10", {"--png-level"});
    usage("StartTimeInfinite", small + " --start-time inf", {"--start-time"});
    usage("StartTimeHuge", small + " --start-time 1e300", {"--start-time"});
    usage("MouseNan", small + " --mouse nan,nan", {"--mouse nan,nan"});
    usage("MouseBeyondFloat", small + " --mouse 1e39,0", {"--mouse 1e39,0"});
    usage("MouseOneNumber", small + " --mouse 3", {"--mouse 3"});
    usage("VideoQualityNegative", "--size 16x8 --frames 2 --out '@D/out/v.mp4' --video-quality -5", {"--video-quality"});
    usage("CaptureEveryZero", small + " --capture-every 0", {"--capture-every"});
    usage("CapturePassE", small + " --capture-pass E", {"--capture-pass E"});
    usage("CapturePassNotInManifest", "--size 16x8 --frames 2 --out '@D/out/f_%04d.exr' --capture-pass 'Buffer C'",
          {"--capture-pass", "Buffer C", kManifestPath});
    usage("CaptureMemoryZero", small + " --capture-memory 0", {"--capture-memory"});
    usage("EncoderThreadsNegative", small + " --encoder-threads -3", {"--encoder-threads"});
    usage("UnknownOption", small + " --bogus", {"--bogus"});
    add({"MissingTarget", toy(), "run --size 16x8 --frames 2 --out '@D/out/f_%04d.png'", 2, {"target"}, "usage"});
    usage("OutUnsupportedFormat", "--size 16x8 --frames 2 --out '@D/out/x.txt'", {"--out", ".txt"}, "usage.out");
    usage("OutTwoFrameNumbers", "--size 16x8 --frames 2 --out '@D/out/a_%d_%d.png'", {"--out", "only once"}, "usage.out");
    usage("OutWithoutFrameNumber", "--size 16x8 --frames 3 --out '@D/out/one.png'", {"--out", "%04d"});
    usage("OutNameLongerThan255Bytes", "--size 16x8 --frames 2 --out '@D/out/" + std::string(260, 'n') + "_%d.png'",
          {"--out", "255"});
    usage("WindowWithHeadless", small + " --window --headless", {"--window", "--headless"});
    usage("WatchWithWindow", small + " --watch --window", {"--watch"});
    usage("FrameRangeBackwards", "--size 16x8 --frames 10 --out '@D/out/f_%04d.png' --frame-range 5:2",
          {"--frame-range 5:2"});
    usage("FrameRangeNotNumbers", small + " --frame-range a:b", {"--frame-range a:b"});
    usage("ShardBeyondLast", small + " --shard 4/4", {"--shard 4/4"});
    usage("ShardOfZeroParts", small + " --shard 0/0", {"--shard 0/0"});
    usage("CheckpointEveryZero", small + " --checkpoint '@D/c.ckpt' --checkpoint-every 0", {"--checkpoint-every"});
    usage("CheckpointEveryWithoutCheckpoint", small + " --checkpoint-every 3", {"--checkpoint-every", "--checkpoint FILE"});
    usage("CheckpointWithWatch", small + " --checkpoint '@D/c.ckpt' --watch", {"--checkpoint", "--watch"});
    usage("FrameTimeoutNegative", small + " --frame-timeout -1", {"--frame-timeout"});
    usage("CompileTimeoutNan", small + " --compile-timeout nan", {"--compile-timeout"});
    usage("MediaFileWithoutEquals", small + " --media-file abc", {"--media-file abc", "ID=FILE"});
    usage("DateGarbage", small + " --date garbage", {"--date", "garbage"});
    usage("DateImpossible", small + " --date 2024-02-30T10:00:00", {"--date", "2024-02-30"});
    add({"EglPlatformUnknown", toy(), runToy(), 2, {"TOYHOST_EGL_PLATFORM=bogus"}, "usage", 1, Mount::None,
         "TOYHOST_EGL_PLATFORM=bogus"});
    add({"InspectRegionEmpty", toy(), "inspect '@D/img.png' --region 0,0,0,0", 2, {"--region 0,0,0,0"}, "usage", 1,
         Mount::None, "", "run '@D/toy' --size 4x4 --frames 1 --quiet --out '@D/img.png'"});
    // Once defects: an empty argument was dropped (`--size ""` rendered 800x450), printed invisibly
    // ("argument was not expected: ") or gave "file not found" naming nothing.
    add({"EmptyTarget", toy(), "run '' --size 16x8", 2, {"toyhost run: argument 2 is empty (\"\")"}, "usage"});
    add({"EmptyExtraArgument", toy(), "run '@D/toy' '' --size 16x8", 2, {"argument 3 is empty"}, "usage"});
    add({"EmptyOptionValue", toy(), "run '@D/toy' --size '' --frames 1", 2, {"--size: the value is empty"}, "usage"});
    add({"EmptyValueAfterEquals", toy(), "run '@D/toy' --mouse= --frames 1", 2, {"--mouse: the value after '=' is empty"},
         "usage"});
    // Once a defect (issue 27): an unknown command said "A subcommand is required".
    add({"UnknownCommand", toy(), "publish '@D/toy'", 2, {"unknown command \"publish\"", "known: run,"}, "usage"});
    add({"MisspelledCommand", toy(), "rnu '@D/toy'", 2, {"unknown command \"rnu\"", "did you mean \"run\""}, "usage"});
    add({"ShadertoyGivenAsCommand", toy(), "'@D/toy' --frames 1", 2, {"to run that shadertoy, toyhost run @D/toy"},
         "usage"});
    add({"EmptyCompareSide", toy(), "compare '' '@D/toy'", 2, {"toyhost compare: argument 2 is empty"}, "usage"});
    add({"NewUnknownPass", {}, "new '@D/out/n' --passes a,e", 2, {"--passes", "\"e\""}, "usage"});
    // Once unclear (issue 46): these reached Mesa's preprocessor, whose errors named
    // "<toyhost header>:57:12" and no --define, or blamed the user's correct next line.
    usage("DefineTrailingBackslash", small + " --define 'A=1\\'", {"--define", "'A'", "continue the #define"});
    usage("DefineOpenComment", small + " --define 'A=1 /*'", {"--define", "'A'", "does not close"});
    usage("DefineDirective", small + " --define 'X=#error boom'", {"--define", "'X'", "'#'"});
    usage("DefineNamedDefined", small + " --define defined", {"--define", "'defined'", "operator"});
    usage("DefineNotAscii", small + " --define 'X=\xc3\xa9'", {"--define", "'X'", "character set"});

    // Once defects (issue 46): a checkpoint of other defines was said, then every pass that uses a
    // define was compiled without it ("X undeclared"); a lone file's common.glsl that is a link to
    // nothing was skipped without a word; a NUL byte in a manifest read as its end; 1e400 was
    // reported in the parser's words without line:col.
    const std::string usesX = "void mainImage(out vec4 c, in vec2 p) { c = vec4(X); }\n";
    add({"ResumeWithOtherDefines", toy(kManifest, {{"toy/image.glsl", usesX}}),
         runToy("--define X=0.7 --resume '@D/ck'"), 1, {"@D/ck", "other code"}, "checkpoint.mismatch", 1, Mount::None, "",
         "run '@D/toy' --size 16x8 --frames 2 --quiet --define X=0.5 --checkpoint '@D/ck'"});
    add({"LoneFileCommonLinkToNothing", {{"lone/image.glsl", kImage}, {"lone/common.glsl", "<link:gone.glsl>"}},
         "run '@D/lone/image.glsl' --size 16x8 --frames 1 --quiet --out '@D/out/f.png'", 1,
         {"@D/lone/common.glsl", "symbolic link to gone.glsl, which does not exist"}, "io.not-found"});
    add({"ManifestNulByte", toy("{\"passes\": {\"Image\": {\"source\": \"image.glsl\"}}}\n\0"s), runToy(), 1,
         {kManifestPath + ":2:1", "NUL byte"}, "manifest.json"});
    add({"ManifestNumberBeyondDouble", toy(R"({"defaults": {"fps": 1e400}, "passes": {"Image": {"source": "image.glsl"}}})"),
         runToy(), 1, {kManifestPath + ":1:22", "1e400 is beyond the range of numbers"}, "manifest.json"});

    // ---- files named on the command line: exit 1, the file named ---------------------------------
    add({"TargetMissing", {}, "run '@D/nothere' --size 16x8 --frames 2 --quiet --out '@D/out/f_%04d.png'", 1,
         {"@D/nothere"}, "io.not-found"});
    add({"FolderWithoutManifest", {{"toy/image.glsl", kImage}}, runToy(), 1, {"@D/toy/manifest.json"}, "io.not-found"});
    add({"TargetIsDevZero", {}, "run /dev/zero --size 16x8 --frames 2 --quiet --out '@D/out/f_%04d.png'", 1,
         {"/dev/zero", "not a regular file"}, "io.not-a-file"});
    add({"InspectMissingFile", {}, "inspect '@D/none.exr'", 1, {"@D/none.exr"}, "io.not-found"});
    add({"InspectNotAnImage", {{"junk.png", "\x89PNG but not really\x01\x02\x03"s}}, "inspect '@D/junk.png'", 1,
         {"@D/junk.png"}, "image.decode"});
    add({"InspectRegionOutsideImage", toy(), "inspect '@D/img.png' --region 0,0,8,8", 1, {"@D/img.png", "4x4"},
         "inspect.region", 1, Mount::None, "", "run '@D/toy' --size 4x4 --frames 1 --quiet --out '@D/img.png'"});
    add({"ImportMissingExport", {}, "import '@D/none.json' '@D/out/port'", 1, {"@D/none.json"}, "io.not-found"});
    add({"ImportBrokenExport", exportFile(apiExport(R"({"a": 1})")), "import '@D/export.json' '@D/out/port'", 1,
         {"@D/export.json", "Shader.renderpass"}, "export.shape"});
    add({"NewIntoExistingFolder", {{"out/mine/manifest.json", kManifest}}, "new '@D/out/mine'", 1,
         {"@D/out/mine", "already exists"}});
    add({"ResumeMissingCheckpoint", toy(), runToy("--resume '@D/none.ckpt'"), 1, {"@D/none.ckpt"}, "io.not-found"});
    add({"ResumeGarbageCheckpoint", toy(kManifest, {{"junk.ckpt", "garbage\n"}}), runToy("--resume '@D/junk.ckpt'"),
         1, {"@D/junk.ckpt", "TOYHOST-CHECKPOINT"}, "checkpoint.format"});
    add({"ResumeWithOtherSize", toy(), runToyBare("--size 32x8 --frames 4 --out '@D/out/f_%04d.png' --resume '@D/a.ckpt'"),
         2, {"@D/a.ckpt", "--size 16x8"}, "usage.resume", 1, Mount::None, "",
         "run '@D/toy' --size 16x8 --frames 2 --quiet --checkpoint '@D/a.ckpt'"});
    add({"ResumeWithOtherCode", toy(kManifest, {{"toy/other.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n"},
                                               {"toy/other.json", R"({"passes": {"Image": {"source": "other.glsl"}}})"}}),
         "run '@D/toy/other.json' --quiet --frames 4 --out '@D/out/f_%04d.png' --resume '@D/a.ckpt'", 1,
         {"@D/a.ckpt", "other code"}, "checkpoint.mismatch", 1, Mount::None, "",
         "run '@D/toy' --size 16x8 --frames 2 --quiet --checkpoint '@D/a.ckpt'"});
    add({"MediaFileMissing", toy(), runToy("--media-file 'Abstract 3=@D/none.jpg'"), 1, {"@D/none.jpg", "--media-file"},
         "io.not-found"});
    // Once a defect: a --media folder that does not exist was silently ignored.
    add({"MediaFolderMissing", toy(), runToy("--media '@D/nofolder'"), 1, {"@D/nofolder", "--media"}});

    // ---- the manifest: exit 1, the manifest and the JSON field named ----------------------------
    add({"ManifestInvalidJson", toy("{\n  \"passes\": {\n    \"Image\": { \"source\": \"image.glsl\" },\n  }\n}\n"), runToy(),
         1, {kManifestPath + std::string(":4:3: error: invalid JSON: found '}' after a comma")}, "manifest.json"});
    add({"ManifestEmpty", toy(""), runToy(), 1, {kManifestPath + std::string(":1:1: error: invalid JSON: the text ends too early")}, "manifest.json"});
    add({"ManifestNotAnObject", toy("[1, 2]"), runToy(), 1, {kManifestPath, "JSON object"}, "manifest.json"});
    add({"ManifestTrailingByte", toy(kManifest + "\xff"), runToy(), 1, {kManifestPath + std::string(":1:48: error: invalid JSON")},
         "manifest.json"});
    add({"ManifestIsDevZero", {{"toy/manifest.json", "<link:/dev/zero>"}, {"toy/image.glsl", kImage}}, runToy(), 1,
         {"@D/toy/manifest.json", "not a regular file"}, "io.not-a-file"});
    add({"ManifestUnknownField", toy(R"({"passes": {"Image": {"source": "image.glsl"}}, "pases": 1})"), runToy(), 1,
         {kManifestPath, "\"pases\"", "did you mean \"passes\""}, "manifest.unknown-field"});
    add({"PassUnknownField", toy(R"({"passes": {"Image": {"source": "image.glsl", "chanels": {}}}})"), runToy(), 1,
         {kManifestPath, "passes.\"Image\"", "did you mean \"channels\""}, "manifest.unknown-field"});
    add({"ManifestDuplicateKey",
         toy(R"({"passes": {"Image": {"source": "image.glsl"}, "Image": {"source": "image.glsl"}}})"), runToy(), 1,
         {kManifestPath, "passes.Image", "more than once"}, "json.duplicate-key"});
    add({"ManifestWithoutImage", toy(R"({"passes": {"Buffer A": {"source": "image.glsl"}}})"), runToy(), 1,
         {kManifestPath, "passes", "\"Image\" pass is missing"}, "manifest.missing"});
    // Once a defect: one typo gave a second line, 'passes: the "Image" pass is missing'.
    add({"PassNameWithTrailingSpace", toy(R"({"passes": {"Image ": {"source": "image.glsl"}}})"), runToy(), 1,
         {kManifestPath, "passes.\"Image \"", "did you mean \"Image\""}, "manifest.unknown-pass"});
    add({"PassNotAnObject", toy(R"({"passes": {"Image": "image.glsl"}})"), runToy(), 1, {kManifestPath, "passes.\"Image\""},
         "manifest.type"});
    add({"PassWithoutSource", toy(R"({"passes": {"Image": {}}})"), runToy(), 1,
         {kManifestPath, "passes.\"Image\"", "\"source\" is missing"}, "manifest.missing"});
    add({"SourceFileMissing", toy(R"({"passes": {"Image": {"source": "nope.glsl"}}})"), runToy(), 1,
         {kManifestPath, "passes.\"Image\".source", "@D/toy/nope.glsl", "file not found"}, "io.not-found"});
    add({"SourceIsAFolder", toy(R"({"passes": {"Image": {"source": "folder"}}})", {{"toy/folder", "<folder>"}}), runToy(), 1,
         {kManifestPath, "passes.\"Image\".source", "@D/toy/folder", "folder"}, "io.not-a-file"});
    add({"SourceIsAFifo", toy(R"({"passes": {"Image": {"source": "fifo.glsl"}}})", {{"toy/fifo.glsl", "<fifo>"}}), runToy(),
         1, {kManifestPath, "passes.\"Image\".source", "@D/toy/fifo.glsl", "FIFO"}, "io.not-a-file"});
    add({"CommonFileMissing", toy(R"({"common": "nocommon.glsl", "passes": {"Image": {"source": "image.glsl"}}})"), runToy(),
         1, {kManifestPath, "common", "@D/toy/nocommon.glsl"}, "io.not-found"});
    add({"NameEmpty", toy(R"({"name": "", "passes": {"Image": {"source": "image.glsl"}}})"), runToy(), 1,
         {kManifestPath, "\"name\" must be a non-empty string, not an empty string"}, "manifest.type"});
    add({"CommonNotAString", toy(R"({"common": 5, "passes": {"Image": {"source": "image.glsl"}}})"), runToy(), 1,
         {kManifestPath, "\"common\""}, "manifest.type"});
    // Once a defect: one typo gave a second line, 'needs exactly one of "buffer", "texture", ...'.
    add({"ChannelUnknownKey", toy(manifestWithChannel(R"({"bufer": "A"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "did you mean \"buffer\""}, "manifest.unknown-field"});
    add({"ChannelNameTypo", toy(R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChanel0": {"buffer": "A"}}}}})"),
         runToy(), 1, {kManifestPath, "passes.\"Image\".channels", "did you mean \"iChannel0\""}, "manifest.unknown-field"});
    add({"ChannelWithTwoSources", toy(manifestWithChannel(R"({"buffer": "A", "keyboard": true})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "exactly one of"}, "manifest.value"});
    add({"ChannelsFiveEntries",
         toy(R"({"passes": {"Image": {"source": "image.glsl", "channels": [null, null, null, null, {"buffer": "A"}]}}})"),
         runToy(), 1, {kManifestPath, "passes.\"Image\".channels", "at most 4"}, "manifest.value"});
    add({"BufferE", toy(manifestWithChannel(R"({"buffer": "E"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "buffer \"E\""}, "manifest.reference"});
    add({"BufferNotDefined", toy(manifestWithChannel(R"({"buffer": "B"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "Buffer B"}, "manifest.reference"});
    add({"TextureMissing", toy(manifestWithChannel(R"({"texture": "gone.png"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "@D/toy/gone.png", "file not found"}, "io.not-found"});
    add({"TextureIsAFolder", toy(manifestWithChannel(R"({"texture": "pics"})"), {{"toy/pics", "<folder>"}}), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "@D/toy/pics", "folder"}, "io.not-a-file"});
    add({"TextureSymlinkLoop", toy(manifestWithChannel(R"({"texture": "loop.png"})"), {{"toy/loop.png", "<link:loop.png>"}}),
         runToy(), 1, {kManifestPath, "passes.\"Image\".channels.iChannel0", "@D/toy/loop.png", "loop"}, "io.link-loop"});
    add({"TextureNotAnImage",
         toy(manifestWithChannel(R"({"texture": "bad.png"})"), {{"toy/bad.png", "\x13\x37 not an image at all \x00\xff\xfe"s}}),
         runToy(), 1, {"@D/toy/bad.png", "Image / iChannel0", "decode"}, "image.decode"});
    // A few hundred bytes declaring 16000x16000 (once decoded into 1 GB, 3.7 GB with its mip levels
    // and texture, for 9 s): refused from the header as too small for its blocks.
    add({"TextureJpegDeclaringMoreThanItHolds",
         toy(manifestWithChannel(R"({"texture": "claims.jpg"})"), {{"toy/claims.jpg", greyJpeg(16000, 16000, 64)}}),
         runToy(), 1, {"@D/toy/claims.jpg", "Image / iChannel0", "16000x16000", "4000000 blocks", "500000 bytes"},
         "image.decode"});
    // Every scan of a progressive JPEG is a pass over the picture: 330 KB of 20000 scans decoded for
    // minutes. More than 500 scans are refused when the decoder reaches the 501st.
    add({"TextureJpegOfTooManyScans",
         toy(manifestWithChannel(R"({"texture": "scans.jpg"})"), {{"toy/scans.jpg", greyJpeg(2048, 2048, 65536, 1000)}}),
         runToy(), 1, {"@D/toy/scans.jpg", "Image / iChannel0", "more than 500 scans"}, "image.decode"});
    add({"KeyboardWithFilter", toy(manifestWithChannel(R"({"keyboard": true, "filter": "linear"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "\"filter\""}, "manifest.value"});
    add({"VflipOnBuffer", toy(manifestWithBufferA(R"({"buffer": "A", "vflip": true})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "\"vflip\""}, "manifest.value"});
    add({"FilterUnknown", toy(manifestWithChannel(R"({"media": "Gray Noise Medium", "filter": "fitler"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "filter \"fitler\""}, "manifest.value"});
    add({"WrapUnknown", toy(manifestWithChannel(R"({"media": "Gray Noise Medium", "wrap": "mirror"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "wrap \"mirror\""}, "manifest.value"});
    add({"StockMediaHashTypo", toy(manifestWithChannel(R"({"media": ")" + kGrayNoiseTypo + R"("})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", kGrayNoiseTypo, kGrayNoise, "Gray Noise Medium"},
         "manifest.media-near-miss"});
    add({"StockMediaNameTypo", toy(manifestWithChannel(R"({"media": "Abstrac 3"})")), runToy(), 1,
         {kManifestPath, "passes.\"Image\".channels.iChannel0", "did you mean \"Abstract 3\""}, "manifest.media-near-miss"});
    add({"MediaOverrideMissing",
         toy(R"({"media": {"Abstract 3": "my/abstract3.jpg"}, "passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"media": "Abstract 3"}}}}})"),
         runToy(), 1, {kManifestPath, "media.\"Abstract 3\"", "@D/toy/my/abstract3.jpg"}, "io.not-found"});
    add({"DefaultsBadSize", toy(R"({"defaults": {"size": "0x5"}, "passes": {"Image": {"source": "image.glsl"}}})"),
         "run '@D/toy' --quiet --frames 2 --out '@D/out/f_%04d.png'", 1, {kManifestPath, "defaults.size", "0x5"},
         "manifest.value"});
    add({"DefaultsBadFps", toy(R"({"defaults": {"fps": -3}, "passes": {"Image": {"source": "image.glsl"}}})"),
         "run '@D/toy' --quiet --size 16x8 --frames 2 --out '@D/out/f_%04d.png'", 1, {kManifestPath, "defaults.fps", "-3"},
         "manifest.value"});
    add({"DefaultsBadFrames", toy(R"({"defaults": {"frames": 0}, "passes": {"Image": {"source": "image.glsl"}}})"),
         "run '@D/toy' --quiet --size 16x8 --out '@D/out/f_%04d.png'", 1, {kManifestPath, "defaults.frames"},
         "manifest.value"});
    // Once a defect: 1e400 was nlohmann's exception text, without the JSON field or a position.
    add({"NumberBeyondDouble", toy(R"({"defaults": {"frames": 1e400}, "passes": {"Image": {"source": "image.glsl"}}})"),
         runToy(), 1, {kManifestPath, "1e400", "defaults.frames"}});
    add({"SeveralProblemsAtOnce",
         toy(R"({"nmae": "x", "passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "E"}, "iChannel1": {"texture": "gone.png", "wrap": "mirror"}}}}})"),
         runToy(), 1, {"did you mean \"name\"", "buffer \"E\"", "@D/toy/gone.png", "wrap \"mirror\""}, "", 4});

    // ---- shader code: exit 1, FILE:LINE:COL and the pass ----------------------------------------
    add({"ShaderNulByte", toy(kManifest, {{"toy/image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\0\n}\n"s}}),
         runToy(), 1, {"@D/toy/image.glsl:2:19:", "Image", "NUL"}, "shader.nul"});
    add({"ShaderNonAsciiOutsideComment",
         toy(kManifest, {{"toy/image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    float \xc3\xa9 = 1.0;\n    c = vec4(1.0);\n}\n"}}),
         runToy(), 1, {"@D/toy/image.glsl:2:11:", "Image", "U+00E9"}, "shader.non-ascii"});
    // Once a defect: a binary file gave exactly 100 errors and no word that more were left out.
    {
        std::string binary;
        for (int i = 0; i < 5000; ++i) binary += (i % 50 == 49) ? '\n' : static_cast<char>(0x80 + i % 100);
        add({"ShaderBinaryBytesAreCountedPastTheCap", toy(kManifest, {{"toy/image.glsl", binary}}), runToy(), 1,
             {"@D/toy/image.glsl:1:1:", "and 4880 more NUL or non-ASCII bytes up to line 100", "is this file GLSL"},
             "shader.non-ascii", 21});
    }
    add({"ShaderCompileError", toy(kManifest, {{"toy/image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0) +;\n}\n"}}),
         runToy(), 1, {"@D/toy/image.glsl:2:20:", "Image"}, "shader.compile"});
    add({"ShaderCompileErrorInBuffer",
         toy(R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"}, "Image": {"source": "image.glsl"}}})",
             {{"toy/buffer_a.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    float x = 1.0;\n    c = vec4(x)\n}\n"}}),
         runToy(), 1, {"@D/toy/buffer_a.glsl:3:16:", "Buffer A", "';' missing at the end of this line"}, "shader.compile"});
    add({"ShaderWithoutMainImage", toy(kManifest, {{"toy/image.glsl", "void notMain(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n"}}),
         runToy(), 1, {"@D/toy/image.glsl", "Image", "mainImage"}, "shader.link"});
    add({"CommonCompileError",
         toy(R"({"common": "common.glsl", "passes": {"Image": {"source": "image.glsl"}}})",
             {{"toy/common.glsl", "float helper() {\n    return 1.0\n}\n"}}),
         runToy(), 1, {"@D/toy/common.glsl:2:15:"}, "shader.compile"});
    // Once a defect: one mistake in Common was reported once per pass that includes it.
    add({"CommonCompileErrorWithThreePasses",
         toy(R"({"common": "common.glsl", "passes": {"Buffer A": {"source": "image.glsl"}, "Buffer B": {"source": "image.glsl"}, "Image": {"source": "image.glsl"}}})",
             {{"toy/common.glsl", "float helper() {\n    return 1.0\n}\n"}}),
         runToy(), 1, {"@D/toy/common.glsl:2:15:"}, "shader.compile"});

    // ---- Shadertoy exports: exit 1, the export and the JSON path or [pass]:LINE ------------------
    add({"ExportShaderNotAnObject", exportFile(R"({"Shader": 5})"), runExport(), 1, {"@D/export.json", "Shader"},
         "export.shape"});
    // Export shapes that are not one runnable shader are named in export terms, not as a bad manifest.
    add({"ExportInfoWithoutRenderpass", exportFile(R"({"info": {"id": "tSt123", "name": "Synthetic"}})"), runExport(), 1,
         {"@D/export.json", "renderpass: is missing"}, "export.shape"});
    add({"ExportArrayOfTwoShaders",
         exportFile(R"([{"ver": "0.1", "info": {"id": "aaa", "name": "A"}, "renderpass": []},
                        {"ver": "0.1", "info": {"id": "bbb", "name": "B"}, "renderpass": []}])"),
         runExport(), 1, {"@D/export.json", "holds 2 shaders", "\"A\" (id aaa)", "one shader per file"}, "export.shape"});
    add({"ExportRenderpassNotAnArray", exportFile(apiExport(R"({"a": 1})")), runExport(), 1,
         {"@D/export.json", "Shader.renderpass", "array"}, "export.shape"});
    add({"ExportWithoutImagePass", exportFile(apiExport("[]")), runExport(), 1, {"@D/export.json", "no image pass"},
         "export.missing"});
    add({"ExportPassWithoutCode",
         exportFile(apiExport(R"([{"inputs": [], "outputs": [{"id": 37, "channel": 0}], "name": "Image", "type": "image"}])")),
         runExport(), 1, {"@D/export.json", "renderpass[0].code"}, "export.missing"});
    add({"ExportInputChannel7", exportFile(apiExport("[" + imagePass(R"([{"id": 257, "type": "buffer", "channel": 7}])") + "]")),
         runExport(), 1, {"@D/export.json", "renderpass[0].inputs[0].channel", "7"}, "export.value"});
    add({"ExportInputUnknownId", exportFile(apiExport("[" + imagePass(R"([{"id": 999, "type": "buffer", "channel": 0}])") + "]")),
         runExport(), 1, {"@D/export.json", "renderpass[0].inputs[0].id", "999", "Image / iChannel0"}, "export.value"});
    add({"ExportInputsNotAnArray", exportFile(apiExport("[" + imagePass(R"({"a": 1})") + "]")), runExport(), 1,
         {"@D/export.json", "renderpass[0].inputs"}, "export.value"});
    add({"ExportDuplicateKey",
         exportFile(R"({"Shader": {"info": {"id": "x", "name": "y"}, "renderpass": [)" + imagePass() + R"(], "renderpass": []}})"),
         runExport(), 1, {"@D/export.json", "Shader.renderpass"}, "json.duplicate-key"});
    add({"ExportCompileErrorInBufferB",
         exportFile(apiExport("[" +
                              apiPass("buffer", "Buffer B", R"([{"id": 258, "channel": 0}])",
                                      R"("void mainImage(out vec4 c, in vec2 p) {\n    float x = 1.0;\n    c = vec4(x) +;\n}\n")") +
                              "," + imagePass() + "]")),
         runExport(), 1, {"@D/export.json [Buffer B]:3:", "Buffer B"}, "shader.compile"});
    add({"ExportCompileErrorInCommon",
         exportFile(apiExport("[" + apiPass("common", "Common", "[]", R"("float helper() {\n    return 1.0\n}\n")") + "," +
                              imagePass() + "]")),
         runExport(), 1, {"@D/export.json [Common]:2:15:"}, "shader.compile"});

    // ---- input scripts: exit 1, the script and the event -----------------------------------------
    auto script = [&](const std::string& name, const std::string& option, const std::string& text,
                      std::vector<std::string> mentions, const std::string& code = "script.event") {
        mentions.insert(mentions.begin(), "@D/script.json");
        add({name, toy(kManifest, {{"script.json", text}}), runToy(option + " '@D/script.json'"), 1, std::move(mentions), code});
    };
    script("MouseScriptNotAnArray", "--mouse-script", R"({"frame": 1})", {"array"}, "script.json");
    script("MouseScriptUnknownType", "--mouse-script", R"([{"frame": 1, "type": "wiggle", "x": 1, "y": 2}])",
           {"event 0", "\"wiggle\""});
    script("MouseScriptMissingX", "--mouse-script", R"([{"frame": 1, "type": "down", "y": 2}])", {"event 0", "\"x\""});
    script("MouseScriptXBeyondFloat", "--mouse-script", R"([{"frame": 1, "type": "down", "x": 1e39, "y": 2}])",
           {"event 0", "\"x\""});
    script("MouseScriptToOnDown", "--mouse-script",
           R"([{"frame": 0, "type": "down", "x": 1, "y": 2}, {"frame": 1, "type": "down", "x": 1, "y": 2, "to": {"frame": 5, "x": 3, "y": 4}}])",
           {"event 1", "\"to\""});
    script("MouseScriptFrameAndTime", "--mouse-script", R"([{"frame": 1, "time": 0.5, "type": "down", "x": 1, "y": 2}])",
           {"event 0", "\"frame\"", "\"time\""});
    script("KeyScriptUnknownKey", "--key-script", R"([{"frame": 1, "type": "down", "key": "spacebar"}])",
           {"event 0", "\"spacebar\""});
    script("KeyScriptCode300", "--key-script", R"([{"frame": 1, "type": "down", "key": 300}])", {"event 0", "300"});
    add({"MouseScriptDevZero", toy(), runToy("--mouse-script /dev/zero"), 1, {"/dev/zero", "not a regular file"},
         "io.not-a-file"});
    add({"KeyScriptMissing", toy(), runToy("--key-script '@D/none.json'"), 1, {"@D/none.json"}, "io.not-found"});

    // ---- outputs: exit 1, the output named, nothing half-written ---------------------------------
    add({"OutFolderIsAFile", toy(kManifest, {{"out/file", "a file where a folder should be"}}),
         runToyBare("--size 16x8 --frames 2 --out '@D/out/file/f_%04d.png'"), 1, {"@D/out/file"}, "io.write"});
    add({"OutVideoFolderIsAFile", toy(kManifest, {{"out/file", "a file where a folder should be"}}),
         runToyBare("--size 16x8 --frames 2 --out '@D/out/file/v.mp4'"), 1, {"@D/out/file"}, "io.write"});
    add({"OutReadOnlyPng", toy(), runToy(), 1, {"@D/out/f_0000.png"}, "io.write", 1, Mount::ReadOnly});
    add({"OutReadOnlyExr", toy(), runToyBare("--size 16x8 --frames 2 --out '@D/out/f_%04d.exr'"), 1, {"@D/out/f_0000.exr"},
         "io.write", 1, Mount::ReadOnly});
    add({"OutReadOnlyVideo", toy(), runToyBare("--size 16x8 --frames 2 --out '@D/out/v.mp4'"), 1, {"@D/out/v.mp4"}, "", 1,
         Mount::ReadOnly, "", "", true});
    add({"DiskFullPng", toy(kManifest, {{"toy/image.glsl", kNoise}}),
         runToyBare("--size 320x180 --frames 3 --png-level 0 --out '@D/out/f_%04d.png'"), 1,
         {"@D/out/f_0000.png", "~no space"}, "io.no-space", 1, Mount::Full});
    add({"DiskFullExr", toy(kManifest, {{"toy/image.glsl", kNoise}}),
         runToyBare("--size 128x128 --frames 3 --out '@D/out/f_%04d.exr'"), 1, {"@D/out/f_0000.exr", "~no space"},
         "io.no-space", 1, Mount::Full});
    add({"DiskFullMp4", toy(kManifest, {{"toy/image.glsl", kNoise}}),
         runToyBare("--size 320x180 --frames 30 --out '@D/out/v.mp4'"), 1, {"@D/out/v.mp4", "~no space"}, "io.no-space", 1,
         Mount::Full, "", "", true});
    // Once defects (issue 46): `ulimit -f` killed the run with SIGXFSZ, leaving the hidden .partial
    // file (tiled and untiled); a full disk during a tiled PNG said "PNG: Write Error" (no reason)
    // and a tiled still went on drawing every tile after its first write failed.
    const auto fileTooLarge = [&](const std::string& name, const std::string& options, const std::string& pattern) {
        const std::string first = pattern.find('%') == std::string::npos ? pattern : "f_0000" + pattern.substr(pattern.size() - 4);
        Case c{name, toy(kManifest, {{"toy/image.glsl", kNoise}}), runToyBare(options + " --out '@D/out/" + pattern + "'"), 1,
               {"@D/out/" + first, "File too large"}, "io.write"};
        c.fileSizeLimit = 64 << 10;
        add(std::move(c));
    };
    fileTooLarge("FileTooLargePng", "--size 320x180 --frames 2 --png-level 0", "f_%04d.png");
    fileTooLarge("FileTooLargeExr", "--size 320x180 --frames 2", "f_%04d.exr");
    fileTooLarge("FileTooLargeTiledPng", "--size 640x360 --tile 64 --frames 1 --png-level 0", "t.png");
    fileTooLarge("FileTooLargeTiledExr", "--size 640x360 --tile 64 --frames 1", "t.exr");
    add({"DiskFullTiledPng", toy(kManifest, {{"toy/image.glsl", kNoise}}),
         runToyBare("--size 640x360 --tile 64 --frames 1 --png-level 0 --out '@D/out/t.png'"), 1,
         {"@D/out/t.png", "No space left on device"}, "io.no-space", 1, Mount::Full});
    add({"DiskFullTiledExr", toy(kManifest, {{"toy/image.glsl", kNoise}}),
         runToyBare("--size 640x360 --tile 64 --frames 1 --out '@D/out/t.exr'"), 1,
         {"@D/out/t.exr", "No space left on device"}, "io.no-space", 1, Mount::Full});
    add({"VideoCodecUnknown", toy(), runToyBare("--size 16x8 --frames 2 --out '@D/out/v.mp4' --codec nosuchcodec"), 1,
         {"@D/out/v.mp4", "nosuchcodec"}, "capture.ffmpeg", 1, Mount::None, "", "", true});
    add({"CheckpointIsAFolder", toy(kManifest, {{"ck", "<folder>"}}), runToy("--checkpoint '@D/ck'"), 2,
         {"--checkpoint", "@D/ck", "is a folder"}, "usage"});

    // ---- the watchdog: exit 124, the pass named ---------------------------------------------------
    add({"WatchdogFrameInImage", toy(kManifest, {{"toy/image.glsl", kEndlessFrame}}),
         runToyBare("--size 320x180 --frames 2 --frame-timeout 1 --out '@D/out/f_%04d.png'"), 124,
         {"Image", "--frame-timeout 1"}, "watchdog.frame"});
    add({"WatchdogFrameInBuffer",
         toy(R"({"passes": {"Buffer A": {"source": "endless.glsl"}, "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A"}}}}})",
             {{"toy/endless.glsl", kEndlessFrame}}),
         runToyBare("--size 320x180 --frames 2 --frame-timeout 1 --out '@D/out/f_%04d.png'"), 124,
         {"Buffer A", "--frame-timeout 1"}, "watchdog.frame"});
    // compare: the draw that never ends is cut off at the limit as in run, not waited for (the
    // frame takes minutes; the case is killed at 60 s, exit 137, if the watchdog does not end it).
    add({"WatchdogFrameInCompare",
         toy(kManifest, {{"toy/image.glsl", kEndlessFrame}, {"ok/manifest.json", kManifest}, {"ok/image.glsl", kImage}}),
         "compare '@D/ok' '@D/toy' --size 320x180 --frames 2 --frame-timeout 1", 124,
         {"@D/toy", "Image", "--frame-timeout 1"}, "watchdog.frame"});
    add({"WatchdogCompile", toy(kManifest, {{"toy/image.glsl", bigShader(3)}}),
         runToyBare("--size 16x8 --frames 1 --compile-timeout 0.5 --out '@D/out/f_%04d.png'"), 124,
         {"Image", "--compile-timeout 0.5"}, "watchdog.compile"});
    return cases;
}

// ---- running a case ---------------------------------------------------------------------------

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::vector<std::string> errorLines(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);)
        if (line.find("error:") != std::string::npos) lines.push_back(line);
    return lines;
}

// Every path under `dir`, relative, hidden ones included; symbolic links are not followed (a case
// may hold a link loop).
void walk(const fs::path& dir, const fs::path& root, std::set<std::string>& paths) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        paths.insert(it->path().lexically_relative(root).string());
        if (fs::is_directory(fs::symlink_status(it->path(), ec))) walk(it->path(), root, paths);
    }
}

std::set<std::string> listTree(const fs::path& dir) {
    std::set<std::string> paths;
    walk(dir, dir, paths);
    return paths;
}

// True when `path` is a folder with no file anywhere under it (empty folders only).
bool holdsNoFile(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(path, ec))) return false;
    for (const std::string& inside : listTree(path))
        if (!fs::is_directory(fs::symlink_status(path / inside, ec))) return false;
    return true;
}

bool shell(const std::string& command) { return std::system(command.c_str()) == 0; }

// Runs toyhost with `arguments`: headless (no display), its temporary files (ffmpeg's log) in
// `tmp`, Mesa's shader cache off (compile times stay what they are), killed after 60 s.
CommandResult runCase(const std::string& arguments, const fs::path& tmp, const std::string& env,
                      long long fileSizeLimit = 0) {
    const std::string limit = fileSizeLimit ? " /usr/bin/prlimit --fsize=" + std::to_string(fileSizeLimit) : "";
    return runCommand("/usr/bin/env", "-u DISPLAY -u WAYLAND_DISPLAY TMPDIR='" + tmp.string() +
                                          "' MESA_SHADER_CACHE_DISABLE=true " + env + limit +
                                          " /usr/bin/timeout -s KILL 60 '" + toyhostBinary().string() + "' " + arguments);
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class BadInput : public ::testing::TestWithParam<Case> {
protected:
    void TearDown() override {
        if (mounted_) {
            shell("umount '" + (dir_ / "out").string() + "' 2>/dev/null");
            mounted_ = false;
        }
        if (chmodded_) fs::permissions(dir_ / "out", fs::perms::owner_all, fs::perm_options::add);
    }

    void makeFiles(const Case& c) {
        for (const auto& [relative, rawContent] : c.files) {
            const fs::path path = dir_ / relative;
            const std::string content = replaceAll(rawContent, "@D", dir_.string());
            fs::create_directories(path.parent_path());
            if (content == "<folder>") fs::create_directories(path);
            else if (content == "<fifo>") ASSERT_EQ(::mkfifo(path.c_str(), 0644), 0) << path;
            else if (content.rfind("<link:", 0) == 0) fs::create_symlink(content.substr(6, content.size() - 7), path);
            else std::ofstream(path, std::ios::binary) << content;
        }
    }

    // Mounts what the case needs on <dir>/out; false (with the reason) when this machine cannot.
    bool mountOut(const Case& c, std::string& whyNot) {
        const fs::path out = dir_ / "out";
        fs::create_directories(out);
        const std::string options = c.mount == Mount::Full ? "size=100k" : "ro,size=100k";
        if (shell("mount -t tmpfs -o " + options + " toyhost-catalogue '" + out.string() + "' 2>/dev/null")) {
            mounted_ = true;
            return true;
        }
        if (c.mount == Mount::ReadOnly && ::geteuid() != 0) {
            fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                     fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
            chmodded_ = true;
            return true;
        }
        whyNot = c.mount == Mount::Full ? "cannot mount a small tmpfs to fill (needs mount rights)"
                                        : "cannot mount a read-only tmpfs, and root ignores chmod 555";
        return false;
    }

    fs::path dir_;
    bool mounted_ = false;
    bool chmodded_ = false;
};

TEST_P(BadInput, FailsCleanly) {
    const Case& c = GetParam();
    if (c.needsFfmpeg && !shell("command -v ffmpeg >/dev/null 2>&1")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    const fs::path caseDir = testOutputDir() / "catalogue" / c.name;
    if (c.mount != Mount::None) shell("umount '" + (caseDir / "out").string() + "' 2>/dev/null");  // a crashed run's
    dir_ = freshOutputDir("catalogue/" + c.name);
    const fs::path tmp = dir_ / "tmp";
    fs::create_directories(tmp);
    makeFiles(c);
    if (HasFatalFailure()) return;
    auto expand = [&](const std::string& text) { return replaceAll(text, "@D", dir_.string()); };
    if (!c.prepare.empty()) {
        const CommandResult prepared = runCase(expand(c.prepare), tmp, "");
        ASSERT_EQ(prepared.exitCode, 0) << "preparing: toyhost " << expand(c.prepare) << "\n" << prepared.output;
    }
    if (c.mount != Mount::None) {
        std::string whyNot;
        if (!mountOut(c, whyNot)) GTEST_SKIP() << whyNot;
    }
    const std::set<std::string> before = listTree(dir_);

    const std::string arguments = expand(c.args);
    const CommandResult result = runCase(arguments, tmp, c.env, c.fileSizeLimit);

    std::vector<std::string> problems;
    if (result.exitCode != c.exit)
        problems.push_back("exit code " + std::to_string(result.exitCode) + ", expected " + std::to_string(c.exit));
    const std::vector<std::string> errors = errorLines(result.output);
    if (static_cast<int>(errors.size()) != c.errors)
        problems.push_back(std::to_string(errors.size()) + " lines with \"error:\", expected " + std::to_string(c.errors));
    std::string message;
    for (const std::string& line : errors) {
        if (line.rfind("toyhost: ", 0) != 0) problems.push_back("an error line not in the form \"toyhost: ...\": " + line);
        message += line + "\n";
    }
    for (const std::string& rawMention : c.mentions) {
        const std::string mention = expand(rawMention);
        const bool found = mention.rfind("~", 0) == 0 ? lower(message).find(lower(mention.substr(1))) != std::string::npos
                                                      : message.find(mention) != std::string::npos;
        if (!found) problems.push_back("the message does not name \"" + mention + "\"");
    }
    if (!c.code.empty() && message.find("[" + c.code + "]") == std::string::npos)
        problems.push_back("the message lacks the code [" + c.code + "]");
    for (const std::string& path : listTree(dir_))
        if (!before.count(path) && !holdsNoFile(dir_ / path)) problems.push_back("left behind: " + (dir_ / path).string());

    if (problems.empty()) return;
    std::string report;
    for (const std::string& problem : problems) report += "  - " + problem + "\n";
    report += "command: toyhost " + arguments + "\nexit code: " + std::to_string(result.exitCode) + "\noutput:\n" +
              result.output;
    ADD_FAILURE() << c.name << ":\n" << report;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInput, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(CatalogueSize, HasAtLeastSixtyFiveCasesWithUniqueNames) {
    const std::vector<Case> cases = catalogue();
    EXPECT_GE(cases.size(), 65u);
    std::set<std::string> names;
    for (const Case& c : cases) EXPECT_TRUE(names.insert(c.name).second) << "two cases named " << c.name;
}

// A valid shader too big for Mesa's compiler stack (10000 statements): toyhost must not crash
// without a word. It may run (exit 0), fail with one message (1) or hit the watchdog (124).
TEST(CatalogueCrash, HugeShaderDoesNotCrashToyhost) {
    const fs::path dir = freshOutputDir("catalogue/HugeShader");
    fs::create_directories(dir / "tmp");
    fs::create_directories(dir / "toy");
    std::ofstream(dir / "toy" / "manifest.json") << kManifest;
    std::ofstream(dir / "toy" / "image.glsl") << bigShader(10);
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);  // a crash must not leave a core file
    const std::string arguments = "run '" + dir.string() + "/toy' --size 16x8 --frames 1 --quiet --frame-timeout 2 " +
                                  "--compile-timeout 20 --out '" + dir.string() + "/out/f_%04d.png'";
    const CommandResult result = runCase(arguments, dir / "tmp", "");
    const std::size_t errors = errorLines(result.output).size();
    // A crash (killed by a signal: Mesa's compiler recursion overflowing a small stack) is a failure
    // like any other; toyhost compiles on a thread with a 1 GiB stack for this.
    const bool clean = (result.exitCode == 0 && errors == 0) || ((result.exitCode == 1 || result.exitCode == 124) && errors == 1);
    EXPECT_TRUE(clean) << "command: toyhost " << arguments << "\nexit code " << result.exitCode << ", " << errors
                       << " error lines\n" << result.output;
    if (result.exitCode != 0) EXPECT_TRUE(holdsNoFile(dir / "out") || !fs::exists(dir / "out"));
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// A valid 16384x16384 PNG (1 GiB decoded) under `ulimit -v 2097152` aborted the CLI with an
// uncaught std::bad_alloc (exit 134): it is one error naming the file and what it needed.
TEST(CatalogueMemory, AHugeTextureUnderALowMemoryLimitIsAnErrorNotAnAbort) {
    const fs::path dir = freshOutputDir("catalogue/HugeTextureLowMemory");
    fs::create_directories(dir / "toy");
    std::ofstream(dir / "toy" / "manifest.json") << manifestWithChannel(R"({"texture": "huge.png"})");
    std::ofstream(dir / "toy" / "image.glsl") << kImage;
    ASSERT_TRUE(writeUniformPng(dir / "toy" / "huge.png", 16384, 16384, {40, 90, 200, 255}));
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);  // an abort must not leave a core file
    const std::string command = "ulimit -v 2097152; MESA_SHADER_CACHE_DISABLE=true '" + toyhostBinary().string() + "' run '" +
                                dir.string() + "/toy' --size 16x8 --frames 1 --quiet --out '" + dir.string() +
                                "/out/f_%04d.png' 2>&1; echo \"exit $?\"";
    std::ofstream(dir / "run.sh") << command << "\n";
    const std::string output =
        runCommand("/usr/bin/env", "-u DISPLAY -u WAYLAND_DISPLAY bash '" + (dir / "run.sh").string() + "'").output;
    EXPECT_NE(output.find("exit 1\n"), std::string::npos) << output;
    const std::vector<std::string> errors = errorLines(output);
    ASSERT_EQ(errors.size(), 1u) << output;
    EXPECT_NE(errors[0].find((dir / "toy" / "huge.png").string()), std::string::npos) << output;
    EXPECT_NE(errors[0].find("not enough memory"), std::string::npos) << output;
    EXPECT_NE(errors[0].find("1.00 GiB for 16384x16384 RGBA"), std::string::npos) << output;
    EXPECT_NE(errors[0].find("[image.too-large]"), std::string::npos) << output;
    EXPECT_TRUE(holdsNoFile(dir / "out") || !fs::exists(dir / "out"));
}

}  // namespace
}  // namespace toyhost::testing
