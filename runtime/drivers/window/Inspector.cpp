#include "drivers/window/Inspector.h"

#include <imgui.h>

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "gl/GlStateGuard.h"
#include "render/Present.h"
#include "session/SessionCore.h"

namespace toyhost {

namespace {

ImTextureID textureId(unsigned int texture) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture));
}

// Enough digits to give the float back exactly.
std::string floatText(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
    return text;
}

std::string rgbaText(const std::array<float, 4>& v) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + std::string.
    std::string text = "(";
    for (int i = 0; i < 4; ++i) {
        if (i) text += ", ";
        text += floatText(v[static_cast<std::size_t>(i)]);
    }
    return text + ")";
}

Diagnostic inspectorNotice(std::string message) {
    Diagnostic d;
    d.severity = Severity::Notice;
    d.code = Code::WindowInspector;
    d.message = "inspector: " + message;
    return d;
}

// The passes with a picture of their own: the buffers, then the Image (a Cube A's faces are not
// one texture a thumbnail can show).
std::vector<PassId> picturePasses(const SessionCore& session) {
    std::vector<PassId> passes;
    for (const PassDesc& pass : session.manifest().passes)
        if (isBuffer(pass.id)) passes.push_back(pass.id);
    std::sort(passes.begin(), passes.end());
    passes.push_back(PassId::Image);
    return passes;
}

}  // namespace

std::array<float, 4> readTexel(const SessionCore& session, PassId pass, int x, int y) {
    const PassOutput out = session.output(pass);
    std::array<float, 4> value{};
    GlStateGuard state;  // the read framebuffer, the pack buffer and alignment
    glBindFramebuffer(GL_READ_FRAMEBUFFER, out.framebuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (out.format == PixelFormat::Rgba32f) {
        glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, value.data());
    } else {
        std::uint8_t bytes[4] = {};
        glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
        for (int c = 0; c < 4; ++c) value[c] = static_cast<float>(bytes[c]) / 255.0f;
    }
    return value;
}

void Inspector::draw(SessionCore& session, const InspectorClock& clock, int framebufferW, int framebufferH,
                     std::vector<Diagnostic>& notices) {
    if (!open_) return;
    const bool shown = session.running() && session.frame() > 0;
    const std::vector<PassId> passes = shown ? picturePasses(session) : std::vector<PassId>{};
    if (shown_ && std::find(passes.begin(), passes.end(), *shown_) == passes.end()) shown_.reset();  // reloaded away

    // The texel under the cursor of the pass shown full-canvas, unless the cursor is on the panel.
    const ImGuiIO& io = ImGui::GetIO();
    PassOutput out;
    PresentRect rect;
    std::optional<std::array<int, 2>> texel;
    if (shown_) {
        out = session.output(*shown_);
        rect = presentRect(out.width, out.height, framebufferW, framebufferH);
        // The cursor names the pixel whose top-left corner it is on: its centre, bottom-left based.
        const double fx = io.MousePos.x + 0.5, fy = framebufferH - (io.MousePos.y + 0.5);
        const int tx = static_cast<int>(std::floor((fx - rect.x) * out.width / rect.width));
        const int ty = static_cast<int>(std::floor((fy - rect.y) * out.height / rect.height));
        if (!io.WantCaptureMouse && io.MousePos.x >= 0 && tx >= 0 && ty >= 0 && tx < out.width && ty < out.height)
            texel = std::array<int, 2>{tx, ty};
    }
    std::optional<std::array<float, 4>> value;
    if (texel) value = readTexel(session, *shown_, (*texel)[0], (*texel)[1]);
    if (texel && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        notices.push_back(inspectorNotice(std::string(passName(*shown_)) + " texel (" + std::to_string((*texel)[0]) +
                                          ", " + std::to_string((*texel)[1]) + ") = " + rgbaText(*value)));

    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("inspector", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    // Thumbnails first, at the panel's top-left corner. Drawn by hand over an invisible button:
    // ImGui's ImageButton takes its id from the texture, which a buffer swaps every frame.
    for (std::size_t i = 0; i < passes.size(); ++i) {
        const PassId id = passes[i];
        const PassOutput o = session.output(id);
        const float w = 64.0f;
        const float h = std::clamp(w * static_cast<float>(o.height) / static_cast<float>(std::max(o.width, 1)), 16.0f, 96.0f);
        ImGui::BeginGroup();
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const ImVec2 end(at.x + w, at.y + h);
        if (ImGui::InvisibleButton(passName(id), ImVec2(w, h))) {
            shown_ = shown_ == id ? std::nullopt : std::optional<PassId>(id);
            notices.push_back(inspectorNotice(shown_ ? std::string(passName(id)) + " full-canvas"
                                                     : std::string("the canvas as usual")));
        }
        ImDrawList& list = *ImGui::GetWindowDrawList();
        list.AddImage(textureId(o.texture), at, end, ImVec2(0, 1), ImVec2(1, 0));
        if (shown_ == id) list.AddRect(at, end, IM_COL32(255, 220, 0, 255), 0.0f, 0, 2.0f);
        ImGui::TextUnformatted(passName(id));
        ImGui::EndGroup();
        if (i + 1 < passes.size()) ImGui::SameLine();
    }
    if (!shown) ImGui::TextUnformatted("waiting for a shadertoy that compiles");
    const int frame = shown ? session.frame() - 1 : -1;
    ImGui::Text("iTime %.3f  iFrame %d", clock.time, frame);
    if (clock.frameRate)
        ImGui::Text("%.1f fps", *clock.frameRate);
    else
        ImGui::TextUnformatted("-- fps");
    if (session.running()) {
        ImGui::Text("iResolution %d x %d", session.width(), session.height());
        const glm::vec4 m = session.mouse();
        ImGui::Text("iMouse %.0f %.0f %.0f %.0f", m.x, m.y, m.z, m.w);
    }
    ImGui::TextUnformatted(clock.paused ? "paused" : "running");
    if (shown_) {
        ImGui::Text("%s full-canvas (NaN/Inf magenta)", passName(*shown_));
        if (value)
            ImGui::Text("(%d, %d) %s", (*texel)[0], (*texel)[1], rgbaText(*value).c_str());
        else
            ImGui::TextUnformatted("point at a texel; a click prints it");
    } else if (shown) {
        ImGui::TextUnformatted("click a thumbnail to show it full-canvas");
    }
    ImGui::End();

    if (shown_) {  // (a thumbnail may have been clicked above)
        out = session.output(*shown_);
        rect = presentRect(out.width, out.height, framebufferW, framebufferH);
        const float top = static_cast<float>(framebufferH - rect.y - rect.height);
        ImGui::GetBackgroundDrawList()->AddImage(textureId(out.texture), ImVec2(static_cast<float>(rect.x), top),
                                                 ImVec2(static_cast<float>(rect.x + rect.width), top + static_cast<float>(rect.height)),
                                                 ImVec2(0, 1), ImVec2(1, 0));
    }
}

}  // namespace toyhost
