// toyhost/Session.h (public API, stable): a shadertoy running, as a program that embeds toyhost
// drives it: create it headless (toyhost's own EGL context) or on the caller's current OpenGL ES 3
// context, step it with a time and input events, read a pass back into memory, or draw its Image
// into the caller's framebuffer. It is toyhost's own session (the one every toyhost command runs:
// same pass order, uniforms, ping-pong, reload rule), behind a small header.
//
// Threads: a session is used from the thread that created it, with its GL context current there
// (a headless session makes its own context current at creation and at every call). A call from
// another thread does nothing and returns a Code::Usage error saying so (restart(), which returns
// nothing, only does nothing).
// Hand the calls to the session's thread instead (Python's sessions do). Mesa's GLSL
// compiler recurses deeply on large shaders: create sessions on a thread with a large stack
// (toyhost uses 1 GiB: runOnGlThread() below), or small shaders only.
//
// Errors are returned, never printed, thrown or turned into exit(); notices (stand-ins used,
// preprocessing) are kept for notices().
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toyhost/Export.h>
#include <toyhost/Input.h>
#include <toyhost/Result.h>
#include <toyhost/Settings.h>
#include <toyhost/Shadertoy.h>

namespace toyhost {

enum class RowOrder { TopFirst, BottomFirst };

// A program's own pixels shown in a channel (Session::setChannel): a video's frame, a simulation's
// field, a model's output. `width` x `height` pixels of `components` values (1: R, sampled as
// (r, 0, 0, 1) as the site's one-channel textures; 3: RGB, alpha 1; 4: RGBA), packed rows in
// `order` (TopFirst: row 0 is the picture's top, at t = 1, as read() gives a frame). The texture's
// size and format follow the array: 8-bit normalised for UInt8, 32-bit floats (unclamped) for
// Float32. Mipmap filtering takes UInt8 only.
struct ChannelArray {
    enum class Type { UInt8, Float32 };
    enum class Filter { Nearest, Linear, Mipmap };
    enum class Wrap { Clamp, Repeat };
    int width = 0;
    int height = 0;
    int components = 4;
    Type type = Type::UInt8;
    const void* data = nullptr;
    std::size_t bytes = 0;  // what `data` holds: width * height * components values
    RowOrder order = RowOrder::TopFirst;
    Filter filter = Filter::Linear;
    Wrap wrap = Wrap::Clamp;
};

// What a hot reload did (Session::reload).
struct Reloaded {
    bool applied = false;           // new code or structure runs now
    bool structureChanged = false;  // passes, bindings or image contents changed: buffers carried over
    std::vector<std::string> recompiled;
    std::vector<Diagnostic> problems;  // empty: everything the shadertoy says runs now
};

// A reload planned ahead (Session::prepareReload): the new shadertoy's files read, its images
// decoded, its videos opened and its shaders' texts prepared, off the session's GL thread; what
// is left for reload(PreparedReload) on that thread is compiling and making textures. Move-only;
// used once.
class TOYHOST_API PreparedReload {
public:
    ~PreparedReload();
    PreparedReload(PreparedReload&&) noexcept;
    PreparedReload& operator=(PreparedReload&&) noexcept;

    struct Plan;  // toyhost's own (not part of the stable API)

private:
    friend class Session;
    explicit PreparedReload(std::unique_ptr<Plan> plan);
    std::unique_ptr<Plan> plan_;
};

class TOYHOST_API Session {
public:
    // With toyhost's own headless EGL context (no display needed). The environment variable
    // TOYHOST_EGL_PLATFORM chooses its EGL platform as for the toyhost commands: surfaceless
    // (Mesa), device (EGL_EXT_platform_device, e.g. NVIDIA's headless driver) or automatic (unset:
    // surfaceless when available, else the first device); another value is a usage error.
    static Result<std::unique_ptr<Session>> createHeadless(const Shadertoy& shadertoy, const SessionSettings& settings = {});
    // On the caller's OpenGL ES 3 context, current on this thread. Every call that renders saves
    // the GL state toyhost touches (framebuffer bindings, program, viewport, active texture and
    // the textures and samplers of units 0-3, vertex array, blending, depth test, scissor test,
    // pixel-store alignments and buffer bindings) and restores it before returning.
    static Result<std::unique_ptr<Session>> createOnCurrentContext(const Shadertoy& shadertoy,
                                                                   const SessionSettings& settings = {});
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // Renders the next frame at the fixed step (settings.fps), after applying the input scripts'
    // events due before it and then `events`, in order: the same frames as `toyhost run` with the
    // same settings. Returns once the frame is submitted (glFlush), not drawn: a read() waits for it.
    // An event with a non-finite or out-of-range position (beyond +-1e6 pixels), or a keyCode
    // outside 0..255, is refused naming `mouse` or `key`; nothing renders.
    Status step(std::span<const InputEvent> events = {});
    // Renders the next frame at iTime `time`, with iTimeDelta `timeDelta` and iFrameRate
    // `frameRate` (a real-time loop measures these itself); iDate follows `time`. The input
    // scripts' events of this frame number come first, as in step(). Returns once submitted.
    // A non-finite time, a negative or non-finite timeDelta or frameRate is refused naming
    // `time`, `time_delta` or `frame_rate`.
    Status stepAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> events = {});
    // Goes on until iFrame `frame` is the next frame, reading nothing back: the frames before it
    // are simulated at the fixed step (with the input scripts' events) as `toyhost run
    // --frame-range` and `--shard` reach their first frame: buffers and Cube A run, Image is not
    // rendered; a shadertoy without them renders nothing at all (only iFrame and the input
    // advance), unless its Image may discard (it keeps earlier frames' pixels: then it is drawn). From `frame` on, step() and render() give the frames of a session that stepped
    // there, byte for byte. `frame` before frame() is refused with a Code::Usage error (a session
    // only goes forward; restart() goes back to 0); frame() itself does nothing. New member only.
    Status seek(int frame);
    int frame() const;  // iFrame of the next frame
    // The iTime step() gives frame `frame` (settings.startTime + frame / settings.fps).
    double timeOf(int frame) const;
    int width() const;
    int height() const;

    // A pass's latest output ("Image", "Buffer A" .. "Buffer D") as width * height * 4 values,
    // RGBA, rows in `order`: 8-bit as the screen shows it (a buffer's floats clamped and rounded),
    // or floats (Image's are the 8-bit levels / 255 unless floatImage). `out` must hold exactly
    // width() * height() * 4 values.
    Status read(std::string_view pass, std::span<std::uint8_t> out, RowOrder order = RowOrder::TopFirst) const;
    Status read(std::string_view pass, std::span<float> out, RowOrder order = RowOrder::TopFirst) const;

    // Rendering a sequence of frames into memory through toyhost's frame stream, the one its own
    // recordings use: `frames` frames stepped as step() steps them (`events` applied before the
    // first), the frames whose iFrame is a multiple of `every` (counted on iFrame, not from the
    // rendering's start: from iFrame 100, every 30 gives 120, 150, ..., the frames a run from 0
    // captures) and the last read back while the later frames render,
    // each handed to the callback as soon as its read is complete (checked after every frame: a
    // frame never waits for a later one to be rendered or read), at most kRenderReadsInFlight
    // reads in flight.
    // Frames are submitted at most two ahead of the GPU's drawing (a GPU would otherwise queue
    // dozens), so that frame() stays near the pictures and a stop leaves little to finish.
    struct RenderRequest {
        int frames = 0;
        int every = 1;
        std::string pass = "Image";  // "Image" or a buffer the shadertoy has, as read()
        std::vector<InputEvent> events;
    };
    static constexpr int kRenderReadsInFlight = 3;
    // A frame handed over: its read is complete. Copy it out with read() during the callback (the
    // pixels are gone once it returns): the values read() of the session gives for that frame.
    class TOYHOST_API RenderedFrame {
    public:
        int frame = 0;  // iFrame of the frame
        int width = 0;
        int height = 0;
        // `out` must hold exactly width * height * 4 values.
        Status read(std::span<std::uint8_t> out, RowOrder order = RowOrder::TopFirst) const;
        Status read(std::span<float> out, RowOrder order = RowOrder::TopFirst) const;

    private:
        friend class Session;
        const void* pixels_ = nullptr;  // the mapped read, rows bottom first
        bool floatPixels_ = false;      // RGBA32F values, else RGBA8
    };
    // Given each frame handed over, in order; returning false stops the rendering (no further
    // frame is rendered or handed over).
    using FrameCallback = std::function<bool(const RenderedFrame&)>;

    // The public handle of toyhost's frame stream into memory, in steps, for a loop that does other
    // work between frames (Python's render() runs one step per GL job). Made by startRendering();
    // used, like the session, on the session's thread, and destroyed before the session.
    class TOYHOST_API Rendering {
    public:
        ~Rendering();  // reads not handed over are dropped
        Rendering(const Rendering&) = delete;
        Rendering& operator=(const Rendering&) = delete;
        // Renders the next frame (when frames are left) and hands every frame whose read is
        // complete to `onFrame`, waiting for a read only when kRenderReadsInFlight are in flight;
        // once every frame is rendered, waits for the reads left and hands them over. Returns
        // whether there is more to do: false once everything was handed over, or after a stop
        // (onFrame's false or stop()). An error ends the rendering (reads in flight are dropped).
        Result<bool> advance(const FrameCallback& onFrame);
        // Asks the rendering to stop before its next frame: from any thread (the one thing a
        // rendering takes from another thread). The next advance() renders nothing and returns
        // false; frames read but not handed over are dropped.
        void stop();
        int framesRendered() const;
        int readsInFlight() const;  // frames read back and not yet handed over

        class Impl;

    private:
        friend class Session;
        explicit Rendering(std::unique_ptr<Impl> impl);
        std::unique_ptr<Impl> impl_;
    };
    // A rendering of `request` (checked now: frames 0 or more, every 1 or more, a pass to read);
    // no frame renders before its first advance().
    Result<std::unique_ptr<Rendering>> startRendering(const RenderRequest& request);
    // The whole rendering: returns once every frame was rendered and handed over, or onFrame
    // returned false, or with the error that stopped it.
    Status render(const RenderRequest& request, const FrameCallback& onFrame);

    // Recording the next frames to files through toyhost's own encoders, as `toyhost run --out`
    // writes them: `out` is a PNG or EXR pattern ("f_%04d.png") or a video ("take.mp4", .webm, .mov,
    // .mkv; needs ffmpeg); `frames` frames are stepped as step() steps them (`events` applied before
    // the first), frames 0, every, 2 * every, ... and the last captured, numbered from 0 as a run's
    // files are. With the session's settings and fresh from its creation, the files are those of
    // `toyhost run` with the same options, byte for byte (a video: the same decoded frames). Checked
    // as --out is (a pattern with a frame number when more than one frame is captured, ffmpeg for a
    // video; stdout is refused). Returns the files written; on an error or a stop nothing half
    // written is left (files complete so far stay; an unfinished video is removed). New member only.
    struct RecordRequest {
        std::string out;
        int frames = 0;
        int every = 1;
        std::string pass = "Image";  // "Image" or a buffer the shadertoy has (EXR: its raw floats)
        std::vector<InputEvent> events;
    };
    Result<std::vector<std::string>> record(const RecordRequest& request);

    // Shows `pixels` in channel `channel` (0..3) of `pass` ("Image", "Buffer A".."Buffer D",
    // "Cube A") from the next frame on, uploaded now (the caller's memory is not kept); call it again
    // before any step() to replace them (a new size or format makes a new texture). The channel must
    // be unbound (its sampler2D then shows the array) or show a picture (an image file or stock
    // texture, replaced); a buffer, cubemap, video or keyboard channel is refused, as are a shape
    // or byte count that do not agree, naming pass and channel. The array stays through restart(),
    // resize() and reloads that keep the channel able to show it. New member only.
    Status setChannel(std::string_view pass, int channel, const ChannelArray& pixels);

    // The Image output as a texture of the session's GL context (for sampling in the caller's own
    // shaders: bottom row first, as GL textures are), valid until the next step() or resize().
    unsigned int imageTexture() const;
    // Draws Image into `framebuffer` (0: the default one) at x, y, width, height (bottom-left
    // origin; scaled with linear filtering when the size differs).
    Status drawImage(unsigned int framebuffer, int x, int y, int width, int height) const;

    // iFrame back to 0 and every buffer cleared (the site's restart).
    void restart();
    // A new canvas size; buffers keep their content bottom-left, iFrame goes on.
    Status resize(int width, int height);
    // Switches to `next` (the same shadertoy's files loaded again): changed code is recompiled (a
    // pass that fails keeps its last good program), a changed structure keeps the buffers that
    // still exist; iFrame and time go on.
    // Plans on the calling thread (files, decoding, media, a preprocessor child): use the two
    // calls below to keep that off the GL thread.
    Result<Reloaded> reload(const Shadertoy& next);
    // The planning half of reload(), callable from any thread while the session is used on its own
    // (it reads only settings fixed at creation); problems found here are reported by reload().
    PreparedReload prepareReload(const Shadertoy& next) const;
    // The applying half, on the session's thread: as reload(next), from `prepared` (made by this
    // session's prepareReload; a moved-from or used one is a usage error).
    Result<Reloaded> reload(PreparedReload prepared);

    // The Sound pass (mainSound) as the site renders it: interleaved stereo samples at 44100 Hz,
    // `seconds` long (0: the site's 180 s; a negative, NaN or infinite length, or more than an
    // hour, is refused naming `seconds`).
    Result<std::vector<float>> renderSound(double seconds = 0);

    // Notices so far (stand-ins used, passes preprocessed as browsers do), oldest first.
    const std::vector<Diagnostic>& notices() const;
    // A description of the GL backend ("EGL surfaceless; OpenGL ES 3.2 Mesa ...").
    std::string backend() const;

    class Impl;

private:
    explicit Session(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Runs `job` on a thread with a stack large enough for Mesa's GLSL compiler and waits for it (a
// session created there must also be used and destroyed there).
TOYHOST_API void runOnGlThread(const std::function<void()>& job);

// What happens when a session's frameTimeout or compileTimeout passes while its thread is still
// inside GL, which cannot be interrupted. By default nothing more: the call returns the error once
// the draw or compile ends, however long that takes. A program that would rather end at once sets
// a handler (toyhost compare prints the diagnostic and exits with 124, as toyhost run does). It is
// called on a watchdog thread, at most once per session, with the diagnostic (its file is the
// shadertoy's), while the session's thread is still stuck; it may end the process. Process-wide;
// an empty handler restores the default.
TOYHOST_API void setWatchdogExpiryHandler(std::function<void(const Diagnostic&)> handler);

}  // namespace toyhost
