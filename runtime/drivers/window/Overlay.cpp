#include "drivers/window/Overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <filesystem>
#include <string>

#include "core/ProblemDigest.h"
#include "session/SessionCore.h"

namespace toyhost {

namespace {

// Debian's fonts-dejavu-core; ImGui's built-in font when it is not installed.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr float kFontPixels = 14.0f;

// Binds an ImGui context for a scope (ImGui keeps the current one in a global).
class CurrentImGui {
public:
    explicit CurrentImGui(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) { ImGui::SetCurrentContext(context); }
    ~CurrentImGui() { ImGui::SetCurrentContext(previous_); }
    CurrentImGui(const CurrentImGui&) = delete;
    CurrentImGui& operator=(const CurrentImGui&) = delete;

private:
    ImGuiContext* previous_;
};

// The problems as stderr writes them (formatDiagnostic), but only the first of each pass, files
// named relative to the shadertoy's folder (core/ProblemDigest.h) and a count of the rest: eight
// problems with absolute paths covered a 640x360 canvas and the last ones were cut without a word.
void drawProblems(const std::vector<Diagnostic>& problems, const std::filesystem::path& folder, int framebufferW,
                  int framebufferH) {
    if (problems.empty()) return;
    const ProblemDigest digest = digestProblems(problems, folder);
    const float w = static_cast<float>(framebufferW), h = static_cast<float>(framebufferH);
    ImGui::SetNextWindowPos(ImVec2(0, h), ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0), ImVec2(w, h));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("problems", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.55f, 1.0f));
    // Each problem's line wrapped to the window so that its place and message are read in a small
    // window; the excerpt is not, so the caret stays under its column.
    for (const Diagnostic& problem : digest.shown) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(formatDiagnostic(problem).c_str());
        ImGui::PopTextWrapPos();
        if (!problem.excerpt.empty()) ImGui::TextUnformatted(problem.excerpt.c_str());
    }
    if (digest.more > 0) ImGui::Text("+%zu more (all of them on stderr)", digest.more);
    ImGui::PopStyleColor();
    ImGui::End();
}

}  // namespace

Result<std::unique_ptr<Overlay>> Overlay::create() {
    std::unique_ptr<Overlay> overlay(new Overlay());
    overlay->context_ = ImGui::CreateContext();
    CurrentImGui current(overlay->context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // nothing written next to the user's files
    io.LogFilename = nullptr;
    std::error_code ec;
    if (!std::filesystem::exists(kFontFile, ec) || !io.Fonts->AddFontFromFileTTF(kFontFile, kFontPixels))
        io.Fonts->AddFontDefault();
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    Result<std::unique_ptr<OverlayRenderer>> renderer = OverlayRenderer::create();
    if (!renderer) return renderer.error();
    overlay->renderer_ = std::move(*renderer);
    overlay->lastFrame_ = std::chrono::steady_clock::now();
    return overlay;
}

Overlay::~Overlay() {
    if (context_) ImGui::DestroyContext(context_);
}

void Overlay::draw(SessionCore& session, const OverlayInput& input, std::vector<Diagnostic>& notices) {
    if (input.framebufferW <= 0 || input.framebufferH <= 0) return;
    if (session.problems().empty() && !inspector_.open()) return;
    CurrentImGui current(context_);
    ImGuiIO& io = ImGui::GetIO();
    const auto now = std::chrono::steady_clock::now();
    io.DeltaTime = std::max(1e-4f, std::chrono::duration<float>(now - lastFrame_).count());
    lastFrame_ = now;
    // Framebuffer pixels throughout: the pointer comes converted (drivers/window/WindowEvents.h).
    io.DisplaySize = ImVec2(static_cast<float>(input.framebufferW), static_cast<float>(input.framebufferH));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.MousePos = input.pointer.x >= 0 ? ImVec2(input.pointer.x, input.pointer.y) : ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = input.pointer.down && inspector_.open();
    ImGui::NewFrame();
    drawProblems(session.problems(), session.plan().shadertoy.manifest.manifestPath.parent_path(), input.framebufferW,
                 input.framebufferH);
    inspector_.draw(session, input.clock, input.framebufferW, input.framebufferH, notices);
    ImGui::Render();
    renderer_->render(*ImGui::GetDrawData(), input.framebufferW, input.framebufferH);
}

}  // namespace toyhost
