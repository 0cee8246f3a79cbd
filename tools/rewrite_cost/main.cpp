// rewrite_cost: for each pass of each Shadertoy export given (files or folders of *.json), the CPU
// time of preparing its fragment shader (assembleFragmentShader: the header, the WebGL rewrite with
// every rule and the plain text; and the rewrite alone) against the CPU time of the driver's
// compile and link of the rewritten text on a headless context. Medians of `--repeat` runs (default
// 5) per pass; one tab-separated line per pass, then a summary. Needs a GL context (llvmpipe is
// fine); run it with MESA_SHADER_CACHE_DISABLE=true so every compile is a real one.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "export/LoadShadertoy.h"
#include "gl/HeadlessContext.h"
#include "gl/ShaderProgram.h"
#include "manifest/ManifestDesc.h"
#include "shader/GlslRewrite.h"
#include "shader/ShaderAssembly.h"

namespace fs = std::filesystem;
using namespace toyhost;

namespace {

double cpuMs(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2.0;
}

struct PassCost {
    std::string name;
    std::size_t bytes = 0;
    double prepare = 0.0;  // ms of thread CPU time
    double rewrite = 0.0;
    double compile = 0.0;  // ms of process CPU time (the driver's threads included)
};

}  // namespace

int main(int argc, char** argv) {
    int repeat = 5;
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc) {
            repeat = std::max(1, std::atoi(argv[++i]));
        } else if (fs::is_directory(arg)) {
            for (const auto& entry : fs::directory_iterator(arg))
                if (entry.path().extension() == ".json") files.push_back(entry.path());
        } else {
            files.emplace_back(arg);
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: rewrite_cost [--repeat N] EXPORT.json|FOLDER...\n");
        return 2;
    }
    std::sort(files.begin(), files.end());
    auto context = createHeadlessContext();
    if (!context) {
        std::fprintf(stderr, "rewrite_cost: %s\n", context.error().text().c_str());
        return 1;
    }
    std::vector<PassCost> costs;
    std::printf("pass\tbytes\tprepare_ms\trewrite_ms\tcompile_ms\tprepare/compile\n");
    for (const fs::path& file : files) {
        Result<ManifestDesc> manifest = loadShadertoy(file);
        if (!manifest) continue;
        for (const PassDesc& pass : manifest->passes) {
            ShaderInputs inputs;
            inputs.pass = pass.id;
            inputs.sound = pass.id == PassId::Sound;
            inputs.common = manifest->commonSource ? &manifest->commonCode : nullptr;
            inputs.code = pass.code;
            for (int c = 0; c < kChannelCount; ++c) inputs.samplers[c] = pass.channels[c].samplerType;
            std::vector<double> prepare, rewrite, compile;
            AssembledShader shader;
            bool compiled = true;
            for (int r = 0; r < repeat && compiled; ++r) {
                double t0 = cpuMs(CLOCK_THREAD_CPUTIME_ID);
                shader = assembleFragmentShader(inputs);
                prepare.push_back(cpuMs(CLOCK_THREAD_CPUTIME_ID) - t0);
                t0 = cpuMs(CLOCK_THREAD_CPUTIME_ID);
                const std::string text = rewriteLikeWebGL(shader.parts.user, shader.parts.options);
                rewrite.push_back(cpuMs(CLOCK_THREAD_CPUTIME_ID) - t0);
                t0 = cpuMs(CLOCK_PROCESS_CPUTIME_ID);
                const ProgramBuild build = buildProgram(fullscreenVertexShader(), shader.text);
                compile.push_back(cpuMs(CLOCK_PROCESS_CPUTIME_ID) - t0);
                compiled = build.ok;
            }
            if (!compiled) continue;  // a pass the driver refuses: no compile time to compare with
            PassCost cost{file.stem().string() + " " + passName(pass.id), shader.parts.user.size(), median(prepare),
                          median(rewrite), median(compile)};
            std::printf("%s\t%zu\t%.3f\t%.3f\t%.2f\t%.4f\n", cost.name.c_str(), cost.bytes, cost.prepare, cost.rewrite,
                        cost.compile, cost.prepare / cost.compile);
            costs.push_back(cost);
        }
    }
    if (costs.empty()) return 1;
    std::vector<double> ratios;
    double total = 0.0, totalCompile = 0.0;
    const PassCost* largest = &costs.front();
    const PassCost* slowest = &costs.front();
    for (const PassCost& c : costs) {
        ratios.push_back(c.prepare / c.compile);
        total += c.prepare;
        totalCompile += c.compile;
        if (c.bytes > largest->bytes) largest = &c;
        if (c.prepare > slowest->prepare) slowest = &c;
    }
    std::printf("# passes %zu; prepare/compile median %.4f, max %.4f; prepare total %.1f ms, compile total %.1f ms\n",
                costs.size(), median(ratios), *std::max_element(ratios.begin(), ratios.end()), total, totalCompile);
    std::printf("# largest pass %s (%zu bytes): prepare %.2f ms, compile %.1f ms; slowest prepare %s: %.2f ms\n",
                largest->name.c_str(), largest->bytes, largest->prepare, largest->compile, slowest->name.c_str(),
                slowest->prepare);
    return 0;
}
