// HostedSession: a SessionCore as a program hosts it on its own thread (the library's Session; a
// driver below the API can do the same): its GL context, toyhost's own headless one made current at
// every call or the caller's current one with the GL state toyhost touches kept; the thread that
// created it, the only one it is used from; its watchdog with the library's expiry handler
// (session/WatchdogSetup.h); its notices kept; and step()'s fixed-step timeline with the frame it
// renders and submits. Needs GL: made, used and destroyed on one thread.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <thread>
#include <type_traits>
#include <new>
#include <vector>

#include "core/Result.h"
#include "gl/GlContext.h"
#include "gl/GlStateGuard.h"
#include "input/InputEvent.h"
#include "session/SessionCore.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"
#include "timing/Timeline.h"

namespace toyhost {

class HostedSession {
public:
    enum class Context { Headless, Current };  // toyhost's own (TOYHOST_EGL_PLATFORM), or the caller's

    HostedSession() = default;  // then start(), on the thread that uses it
    ~HostedSession();           // the GL objects go with the context current, a caller's state kept
    HostedSession(const HostedSession&) = delete;
    HostedSession& operator=(const HostedSession&) = delete;

    // Prepares `options` (prepareSession: every check before GL), makes the context and starts the
    // SessionCore on it. The watchdog's expiry names `options.target` when it names no file.
    Status start(SessionOptions options, Context context);

    // Usable for `call` here: on its own thread (a GL context is current on one thread: from
    // another, EGL would only say EGL_BAD_ACCESS) and its context current.
    Status usable(std::string_view call) const;
    bool onOwnThread() const { return std::this_thread::get_id() == thread_; }
    // The context usable here (the own one made current on this thread; that fails when another
    // thread holds it).
    Status current() const { return ownContext_ ? context_->makeCurrent() : okStatus(); }
    // What every call that renders does around its GL work: the context current (own) or the
    // caller's state kept. An allocation toyhost could not foresee (the foreseeable ones, images and
    // sound, are checked with their size) is an error of the call, never an exception out of it.
    template <class Work>
    auto withGl(Work work) const {
        auto run = [&] {
            if (ownContext_) {
                (void)context_->makeCurrent();
                return work();
            }
            GlStateGuard guard;
            return work();
        };
        using Returned = decltype(run());
        if constexpr (std::is_constructible_v<Returned, Error>) {
            try {
                return run();
            } catch (const std::bad_alloc&) {
                return Returned(Error("out of memory: the system refused an allocation (a larger canvas or more "
                                      "frames in flight than this machine or its ulimit allows?)",
                                      Code::Internal));
            }
        } else {
            return run();
        }
    }
    // A limit that passed while the call ran.
    Status expired() const;

    // A frame rendered as `call` by `work` (usable, the GL work, then the limits).
    template <class Work>
    Status render(std::string_view call, Work work) {
        if (Status made = usable(call); !made) return made;
        Status rendered = withGl(work);
        if (Status limit = expired(); !limit) return limit;
        return rendered;
    }
    // One frame rendered with `time` and `events` and submitted (inside withGl).
    Status draw(const FrameTime& time, std::span<const InputEvent> events);
    // step()'s frame (inside withGl): the timeline's next, its scripted events, then `given`.
    Status next(std::span<const InputEvent> given);
    // stepAt()'s frame (inside withGl): at the caller's time (timeline.atTime), the scripted events
    // of its frame number, then `given`.
    Status nextAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> given);

    // A pass's latest output (the context made usable here), rows bottom first as GL reads them, into
    // `out` (width() * height() * 4 values) with the top row first when `topFirst`: 8-bit as the
    // screen shows it (a buffer's floats clamped and rounded), or floats (an 8-bit target's levels
    // / 255). Waits for the GPU.
    void readPass(PassId pass, std::span<std::uint8_t> out, bool topFirst) const;
    void readPass(PassId pass, std::span<float> out, bool topFirst) const;

    // A caller's input events, checked as the CLI checks --mouse and the input scripts (naming
    // `mouse` or `key`).
    static Status checkEvents(std::span<const InputEvent> events);

    SessionCore& core() { return *core_; }
    const SessionCore& core() const { return *core_; }
    Timeline& timeline() { return *timeline_; }
    const Timeline& timeline() const { return *timeline_; }
    GlContext& context() const { return *context_; }
    const std::vector<Diagnostic>& notices() const { return notices_.kept; }
    // Fixed at start: read from any thread (a reload planned off the session's thread).
    const MediaOptions& media() const { return media_; }
    const MacroDefines& defines() const { return defines_; }

private:
    struct KeptNotices final : SessionObserver {
        void notice(const Diagnostic& notice) override { kept.push_back(notice); }
        std::vector<Diagnostic> kept;
    };
    std::shared_ptr<GlContext> context_;
    bool ownContext_ = false;
    KeptNotices notices_;
    std::unique_ptr<Watchdog> watchdog_;
    std::unique_ptr<SessionCore> core_;
    std::optional<Timeline> timeline_;
    std::vector<InputEvent> events_;  // next()'s scratch: scripted events, then the caller's
    mutable std::vector<std::uint8_t> bytes_;  // readPass()'s scratch
    mutable std::vector<float> floats_;
    std::thread::id thread_ = std::this_thread::get_id();
    MediaOptions media_;
    MacroDefines defines_;
};

}  // namespace toyhost
