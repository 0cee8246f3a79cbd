// RunActivity: what the render thread is doing right now (compiling a pass, waiting for a pass to
// finish drawing, waiting for the encoders or for a video's decoder), and since when, published
// for a watchdog on another thread: GL cannot be interrupted, so a runaway shader can only be
// noticed from outside. The render thread updates it without allocating; any thread reads it.
// No GL needed.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace toyhost {

class RunActivity {
public:
    // WaitingForInput: a frame waits for a video's decoder (media/VideoStream.h), which has not
    // decoded the frame it shows yet; `pass` names the first pass that reads the video.
    // Abandoning: after a stop, the encoders finish the frame each is writing (queued frames are
    // dropped); CPU work of toyhost's own that ends, unlike a draw GL cannot interrupt.
    // DrawCall: inside a pass's draw call (llvmpipe compiles a pass's machine code inside its first
    // draw call: a call that does not return is that compile); Drawing once it returned.
    enum class Phase { Idle, Compiling, Drawing, DrawCall, WaitingForOutput, WaitingForInput, Abandoning };

    struct Snapshot {
        Phase phase = Phase::Idle;
        const char* pass = "";  // a pass name ("Buffer A" .. "Image", "Sound"), or "" when none
        int frame = -1;         // iFrame being drawn (or the Sound pass's block), or -1
        double seconds = 0;     // how long the phase has lasted (wall time)
        std::chrono::steady_clock::time_point since{};  // when it began
        // One draw of a frame that draws its pass several times (supersampling, motion blur:
        // timing/SamplePattern.h): which (0-based) of how many; -1, 0 for a frame's one draw.
        int sample = -1;
        int samples = 0;
    };

    // `pass` must be a string that lives for the whole run (passName() returns such).
    void begin(Phase phase, const char* pass = "", int frame = -1, int sample = -1, int samples = 0) {
        std::lock_guard lock(mutex_);
        phase_ = phase;
        pass_ = pass;
        frame_ = frame;
        sample_ = sample;
        samples_ = samples;
        since_ = std::chrono::steady_clock::now();
    }
    void idle() { begin(Phase::Idle); }
    // The same pass and start time in another phase (a draw call that returned: Drawing goes on).
    void rephase(Phase phase) {
        std::lock_guard lock(mutex_);
        phase_ = phase;
    }
    // What snapshot() said, again, with its start time (the pass published before a draw call).
    void restore(const Snapshot& s) {
        std::lock_guard lock(mutex_);
        phase_ = s.phase;
        pass_ = s.pass;
        frame_ = s.frame;
        sample_ = s.sample;
        samples_ = s.samples;
        since_ = s.since;
    }

    // A watchdog's expiry: the run is ending, so work that can stop between draws (the samples of a
    // frame) stops instead of drawing the rest. Any thread.
    void cancel() { cancelled_.store(true, std::memory_order_release); }
    bool cancelled() const { return cancelled_.load(std::memory_order_acquire); }

    Snapshot snapshot() const {
        std::lock_guard lock(mutex_);
        return {phase_, pass_, frame_, std::chrono::duration<double>(std::chrono::steady_clock::now() - since_).count(),
                since_, sample_, samples_};
    }

private:
    mutable std::mutex mutex_;
    std::atomic<bool> cancelled_{false};
    Phase phase_ = Phase::Idle;
    const char* pass_ = "";
    int frame_ = -1;
    int sample_ = -1;
    int samples_ = 0;
    std::chrono::steady_clock::time_point since_ = std::chrono::steady_clock::now();
};

}  // namespace toyhost
