#include "CompatProbe.h"

#include <GLES3/gl3.h>

#include <chrono>
#include <cmath>

#include "export/LoadShadertoy.h"
#include "gl/EglSurfacelessContext.h"
#include "input/MouseState.h"
#include "graph/PassGraph.h"
#include "media/MediaResolver.h"
#include "media/StockMedia.h"
#include "render/Renderer.h"
#include "run/ChannelImages.h"

namespace toyhost::compat {
namespace fs = std::filesystem;

namespace {

std::string firstLines(const std::string& text, int lines) {
    size_t end = 0;
    for (int i = 0; i < lines && end != std::string::npos; ++i) end = text.find('\n', end ? end + 1 : 0);
    return end == std::string::npos ? text : text.substr(0, end);
}

void judgeOutput(const Renderer& renderer, const ManifestDesc& manifest, ProbeResult& result) {
    std::vector<std::uint8_t> image;
    renderer.readImageRgba8(image);
    result.uniformImage = true;
    for (size_t i = 4; i < image.size() && result.uniformImage; i += 4)
        for (int k = 0; k < 3; ++k)
            if (image[i + k] != image[k]) result.uniformImage = false;
    std::vector<float> floats;
    for (const PassDesc& pass : manifest.passes) {
        if (!isBuffer(pass.id)) continue;
        renderer.readRgba32f(pass.id, floats);
        size_t nan = 0, inf = 0;
        for (float v : floats) {
            nan += std::isnan(v);
            inf += std::isinf(v);
        }
        if (nan || inf)
            result.nonFiniteBuffers.push_back(std::string(passName(pass.id)) + ": " + std::to_string(nan) + " NaN, " +
                                              std::to_string(inf) + " Inf");
    }
}

}  // namespace

ProbeResult runProbe(const fs::path& exportFile, const ProbeSettings& settings) {
    ProbeResult result;
    result.file = exportFile.filename().string();
    result.id = exportFile.stem().string();
    Result<ManifestDesc> manifest = loadShadertoy(exportFile);
    if (!manifest) {
        result.error = firstLines(manifest.error().message, 3);
        return result;
    }
    result.loaded = true;
    result.name = manifest->name;
    result.passes = static_cast<int>(manifest->passes.size()) + (manifest->commonSource ? 1 : 0);
    result.notices = manifest->notices;

    auto context = createEglSurfacelessContext();
    if (!context) {
        result.error = context.error().message;
        return result;
    }
    MediaResolver media;
    for (const fs::path& folder : settings.mediaFolders) media.addSearchFolder(folder);
    ChannelImages images(media, nullptr);
    for (const PassDesc& pass : manifest->passes)
        for (const ChannelDesc& channel : pass.channels)
            if (channel.kind == ChannelKind::StockMedia) {
                auto resolved = media.resolve(channel.media);
                if (resolved && resolved->standIn) {
                    const StockMediaInfo* info = findStockMedia(channel.media);
                    std::string name = info ? std::string(info->name) : channel.media;
                    if (std::find(result.standIns.begin(), result.standIns.end(), name) == result.standIns.end())
                        result.standIns.push_back(name);
                }
            }

    const PassGraph graph = buildPassGraph(*manifest);
    RendererOptions options;
    options.width = settings.width;
    options.height = settings.height;
    auto renderer = Renderer::create(*manifest, graph, options, std::ref(images));
    if (!renderer) {
        result.error = firstLines(renderer.error().message, 4);
        return result;
    }
    result.compiled = true;

    // Like a visitor, the probe drags the mouse across the canvas from frame 1 on, so shaders
    // that show nothing until clicked get their click.
    MouseState mouse;
    auto frameAt = [&](int frame) {
        if (frame == 1) mouse.press(settings.width * 0.3f, settings.height * 0.4f);
        if (frame > 1) {
            const float t = std::min(1.0f, frame / static_cast<float>(std::max(2, settings.frames)));
            mouse.move(settings.width * (0.3f + 0.4f * t), settings.height * (0.4f + 0.2f * t));
        }
        FrameUniforms u;
        u.frame = frame;
        u.time = frame / 60.0f;
        u.timeDelta = 1.0f / 60.0f;
        u.frameRate = 60.0f;
        u.mouse = mouse.uniform();
        (*renderer)->renderFrame(u);
        // Finish each frame so ms/frame is the real shading cost: llvmpipe drops queued work for
        // tiles that a later draw overwrites before anything reads them.
        glFinish();
        mouse.endFrame();
        result.framesRendered = frame + 1;
    };
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < settings.frames; ++frame) frameAt(frame);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.msPerFrame = 1000.0 * seconds / settings.frames;
    if (GLenum error = glGetError(); error != GL_NO_ERROR) result.error = "GL error " + std::to_string(error);
    judgeOutput(**renderer, *manifest, result);
    // Patience for fade-ins and shaders that need time: check every quarter second of iTime.
    for (int frame = settings.frames; result.uniformImage && frame / 60.0 < settings.patienceSeconds; ++frame) {
        frameAt(frame);
        if (frame % 15 != 0) continue;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > settings.wallBudgetSeconds)
            break;
        result.nonFiniteBuffers.clear();
        judgeOutput(**renderer, *manifest, result);
        if (!result.uniformImage) result.firstNonUniformTime = frame / 60.0;
    }
    return result;
}

nlohmann::json toJson(const ProbeResult& r) {
    return {{"file", r.file},
            {"id", r.id},
            {"name", r.name},
            {"passes", r.passes},
            {"loaded", r.loaded},
            {"compiled", r.compiled},
            {"frames_rendered", r.framesRendered},
            {"ms_per_frame", std::round(r.msPerFrame * 100) / 100},
            {"uniform_image", r.uniformImage},
            {"first_non_uniform_time", r.firstNonUniformTime},
            {"non_finite_buffers", r.nonFiniteBuffers},
            {"stand_ins", r.standIns},
            {"notices", r.notices},
            {"error", r.error},
            {"passed", r.passed()}};
}

ProbeResult fromJson(const nlohmann::json& j) {
    ProbeResult r;
    r.file = j.value("file", "");
    r.id = j.value("id", "");
    r.name = j.value("name", "");
    r.passes = j.value("passes", 0);
    r.loaded = j.value("loaded", false);
    r.compiled = j.value("compiled", false);
    r.framesRendered = j.value("frames_rendered", 0);
    r.msPerFrame = j.value("ms_per_frame", 0.0);
    r.uniformImage = j.value("uniform_image", false);
    r.firstNonUniformTime = j.value("first_non_uniform_time", -1.0);
    r.nonFiniteBuffers = j.value("non_finite_buffers", std::vector<std::string>{});
    r.standIns = j.value("stand_ins", std::vector<std::string>{});
    r.notices = j.value("notices", std::vector<std::string>{});
    r.error = j.value("error", "");
    return r;
}

}  // namespace toyhost::compat
