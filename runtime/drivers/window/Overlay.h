// Overlay: what a window draws over its canvas and never into it, with Dear ImGui: the current
// problems of the shadertoy (the text stderr shows: file:line:column, the line, a caret) at the
// bottom of the window for as long as they last, and the F2 inspector (drivers/window/Inspector.h).
// It draws on the default framebuffer after the canvas is presented there, so captured frames
// (--out) and F12 screenshots, which read the passes' own targets, never hold it.
// Needs the window's GL context current (the GL thread) for its whole life.
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "core/Result.h"
#include "drivers/window/Inspector.h"
#include "drivers/window/OverlayRenderer.h"
#include "drivers/window/WindowEvents.h"

struct ImGuiContext;

namespace toyhost {

class SessionCore;

struct OverlayInput {
    int framebufferW = 0, framebufferH = 0;
    WindowEvents::Pointer pointer;
    InspectorClock clock;
};

class Overlay {
public:
    static Result<std::unique_ptr<Overlay>> create();
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    Inspector& inspector() { return inspector_; }
    // Draws the overlay on the default framebuffer; what the inspector reports (picked texels) is
    // appended to `notices`.
    void draw(SessionCore& session, const OverlayInput& input, std::vector<Diagnostic>& notices);

private:
    Overlay() = default;
    ImGuiContext* context_ = nullptr;
    std::unique_ptr<OverlayRenderer> renderer_;
    Inspector inspector_;
    std::chrono::steady_clock::time_point lastFrame_;
};

}  // namespace toyhost
