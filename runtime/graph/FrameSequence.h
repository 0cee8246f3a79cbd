// FrameSequence: the two counters a running shadertoy keeps. `frame` is iFrame: it starts at 0,
// counts rendered frames and goes back to 0 on a restart (the site's Effect.ResetTime). `step`
// picks the ping-pong slots (graph/PassGraph.h): it goes up by one per rendered frame and never
// goes back, not on a restart and not when time is rewound, so "the other slot" is always the
// previous frame's output (a repeated frame included). Pure logic, no GL needed; checked by
// tests/unit/test_diagnostics.cpp (FrameSequence.*).
#pragma once

#include <cstdint>

namespace toyhost {

class FrameSequence {
public:
    int frame() const { return frame_; }             // iFrame of the next frame
    std::uint64_t step() const { return step_; }     // ping-pong step of the next frame
    bool startOfRun() const { return frame_ == 0; }  // the next frame sees cleared buffers

    // After a frame was rendered.
    void advance() {
        ++frame_;
        ++step_;
    }
    // iFrame back to 0; the step goes on.
    void restart() { frame_ = 0; }
    // The frame just rendered is rendered again (a paused window showing a recompile): iFrame back
    // to that frame's, while the step goes on, so each buffer reads the frame's own output and
    // takes one more step. Nothing rendered since the start or a restart: nothing to repeat.
    void repeat() {
        if (frame_ > 0) --frame_;
    }
    // Both counters as a checkpoint saved them.
    void restore(int frame, std::uint64_t step) {
        frame_ = frame;
        step_ = step;
    }

private:
    int frame_ = 0;
    std::uint64_t step_ = 0;
};

}  // namespace toyhost
