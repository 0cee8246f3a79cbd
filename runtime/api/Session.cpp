#include <toyhost/Session.h>

#include <GLES3/gl3.h>

#include <algorithm>
#include <cstring>
#include <deque>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <type_traits>

#include "api/ShadertoyAccess.h"
#include "capture/FrameStream.h"
#include "core/Defaults.h"
#include "gl/CurrentContext.h"
#include "gl/GlStateGuard.h"
#include "gl/GlThread.h"
#include "gl/HeadlessContext.h"
#include "image/PixelConversion.h"
#include "manifest/ManifestDesc.h"
#include "render/PendingReads.h"
#include "session/SessionCore.h"
#include "session/SettingChecks.h"
#include "session/WatchdogSetup.h"
#include "timing/Timeline.h"

namespace toyhost {

namespace {

// Notices as data, for Session::notices().
class KeptNotices final : public SessionObserver {
public:
    void notice(const Diagnostic& notice) override { kept.push_back(notice); }
    std::vector<Diagnostic> kept;
};

// setWatchdogExpiryHandler's handler, read by every session's watchdog when a limit passes.
std::mutex expiryMutex;
std::function<void(const Diagnostic&)>& expiryHandler() {
    static std::function<void(const Diagnostic&)> handler;
    return handler;
}

std::optional<PassId> passNamed(std::string_view name) {
    for (PassId id : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD, PassId::Image})
        if (name == passName(id)) return id;
    return std::nullopt;
}

}  // namespace

class Session::Impl {
public:
    std::shared_ptr<GlContext> context;
    bool ownContext = false;  // headless: made current at every call; else the caller's, guarded
    KeptNotices notices;
    std::unique_ptr<Watchdog> watchdog;
    std::unique_ptr<SessionCore> core;
    std::optional<Timeline> timeline;  // step()'s fixed-step input
    std::vector<InputEvent> events;     // step()'s scratch: scripted events, then the caller's
    mutable std::vector<std::uint8_t> bytes;  // readback scratch
    mutable std::vector<float> floats;
    PendingReads reads;  // queueRead() .. takeRead(); emptied with the context current
    std::thread::id thread = std::this_thread::get_id();  // the one that created the session

    // The session usable for `call` here: on its own thread (a GL context is current on one
    // thread: from another, EGL would only say EGL_BAD_ACCESS) and its context current.
    Status usable(std::string_view call) const {
        if (std::this_thread::get_id() != thread)
            return Error("a session is used on the thread that created it: " + std::string(call) +
                             "() was called from another thread (hand the call to the session's thread, or create "
                             "the session on the thread that uses it)",
                         Code::Usage);
        return current();
    }
    bool onOwnThread() const { return std::this_thread::get_id() == thread; }
    // The media settings, fixed at creation: prepareReload reads them from any thread.
    MediaOptions media;
    MacroDefines defines;  // settings' defines, fixed at creation as the media settings are

    // What every call that renders does around its GL work: the context current (headless) or the
    // caller's state kept (its own context).
    template <class Work>
    auto withGl(Work work) const {
        auto run = [&] {
            if (ownContext) {
                (void)context->makeCurrent();
                return work();
            }
            GlStateGuard guard;
            return work();
        };
        // An allocation toyhost could not foresee (the foreseeable ones, images and sound, are
        // checked with their size) is an error of the call, never an exception out of the API.
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
    // The context usable here (a headless session's is made current on this thread; it fails when
    // another thread holds it).
    Status current() const { return ownContext ? context->makeCurrent() : okStatus(); }
    // One frame rendered with `time` and `events`, submitted to the GPU.
    Status render(const FrameTime& time, std::span<const InputEvent> events);
    // A limit that passed while the call ran.
    Status expired() const {
        if (watchdog)
            if (std::optional<Diagnostic> d = watchdog->expired()) return Error(*d);
        return okStatus();
    }
    Result<PassId> pass(std::string_view name) const {
        std::optional<PassId> id = passNamed(name);
        if (!id || !core->manifest().find(*id))
            return Error("no pass \"" + std::string(name) + "\" to read (Image, or a buffer the shadertoy has)",
                         Code::Usage);
        return *id;
    }
        // A queued read's values into `out`, rows in `order`, converted as the synchronous reads
    // convert (Renderer::readRgba8 / readRgba32f): one pass over the mapped pixels.
    template <class Source, class T>
    static void convertRows(const Source* rows, std::span<T> out, int width, int height, RowOrder order) {
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height; ++y) {
            const Source* from = rows + static_cast<std::size_t>(order == RowOrder::TopFirst ? height - 1 - y : y) * row;
            T* to = out.data() + static_cast<std::size_t>(y) * row;
            if constexpr (std::is_same_v<Source, T>) std::memcpy(to, from, row * sizeof(T));
            else if constexpr (std::is_same_v<T, float>)
                for (std::size_t i = 0; i < row; ++i) to[i] = from[i] / 255.0f;
            else
                for (std::size_t i = 0; i < row; ++i) to[i] = unorm8(from[i]);
        }
    }
    template <class T>
    Result<Session::QueuedRead> takeRead(std::span<T> out, RowOrder order) {
        if (reads.size() == 0) return Error("takeRead: no read is queued (queueRead() first)", Code::Usage);
        const PendingReads::Read read = reads.oldest();
        const std::size_t values = static_cast<std::size_t>(read.width) * read.height * 4;
        if (out.size() != values)
            return Error("takeRead: the destination holds " + std::to_string(out.size()) + " values, the frame " +
                             std::to_string(values) + " (width * height * 4 of the read)",
                         Code::Usage);
        if (Status made = usable("takeRead"); !made) return made.error();
        Status taken = withGl([&] {
            Result<std::span<const std::byte>> pixels = reads.mapOldest();
            if (pixels) {
                if (read.format == PixelFormat::Rgba8)
                    convertRows(reinterpret_cast<const std::uint8_t*>(pixels->data()), out, read.width, read.height, order);
                else
                    convertRows(reinterpret_cast<const float*>(pixels->data()), out, read.width, read.height, order);
            }
            Status released = reads.releaseOldest();
            return pixels ? released : Status(pixels.error());
        });
        if (Status limit = expired(); !limit) return limit.error();
        if (!taken) return taken.error();
        return Session::QueuedRead{read.frame, read.width, read.height};
    }
    template <class T>
    static void copyRows(const std::vector<T>& rows, std::span<T> out, int width, int height, RowOrder order) {
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height; ++y) {
            const int from = order == RowOrder::TopFirst ? height - 1 - y : y;
            std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(from * row), row,
                        out.begin() + static_cast<std::ptrdiff_t>(y * row));
        }
    }
};

namespace {

Result<std::unique_ptr<Session::Impl>> start(const Shadertoy& shadertoy, const SessionSettings& settings, bool headless) {
    auto impl = std::make_unique<Session::Impl>();
    SessionOptions options;
    options.shadertoy = std::make_shared<const ManifestDesc>(ShadertoyAccess::desc(shadertoy));
    options.target = shadertoy.path();
    // The caller's settings as given: prepareSession checks what was given (width 0 is refused as
    // `run --size 0x0` is) and fills what was not, as for a run.
    options.settings = settings;
    // A Session has no watchdog limits unless its settings give them (the commands have theirs).
    if (!options.settings.frameTimeout) options.settings.frameTimeout = defaults::kSessionTimeoutSeconds;
    if (!options.settings.compileTimeout) options.settings.compileTimeout = defaults::kSessionTimeoutSeconds;
    Result<SessionPlan> plan = prepareSession(options);
    if (!plan) return plan.error();
    impl->media = plan->media;
    impl->defines = plan->defines;
    impl->timeline.emplace(timelineOf(*plan));
    WatchdogHooks hooks;
    hooks.expire = [file = shadertoy.path().string()](const Diagnostic& expired, int) {
        std::function<void(const Diagnostic&)> handler;
        {
            std::lock_guard<std::mutex> lock(expiryMutex);
            handler = expiryHandler();
        }
        if (!handler) return;
        Diagnostic named = expired;
        if (named.file.empty()) named.file = file;
        handler(named);
    };
    impl->watchdog = makeWatchdog(plan->options, std::move(hooks));
    if (headless) {
        // The environment chooses the EGL platform, as for every toyhost command.
        Result<EglPlatform> platform = eglPlatformFromEnvironment();
        if (!platform) return platform.error();
        plan->options.eglPlatform = *platform;
        HeadlessOptions headlessOptions;
        headlessOptions.platform = plan->options.eglPlatform;
        Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headlessOptions);
        if (!context) return context.error();
        impl->context = *context;
        impl->ownContext = true;
    } else {
        Result<std::shared_ptr<GlContext>> context = adoptCurrentContext();
        if (!context) return context.error();
        impl->context = *context;
    }
    impl->reads = PendingReads(&impl->context->gpuActivity());
    Session::Impl& s = *impl;
    Result<std::unique_ptr<SessionCore>> core = s.withGl([&] {
        return SessionCore::start(std::move(*plan), s.context, s.notices, s.watchdog.get());
    });
    if (!core) return core.error();
    impl->core = std::move(*core);
    return impl;
}

}  // namespace

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Session::~Session() {
    if (!impl_) return;
    // The GL objects go with their context current; a caller's state is kept.
    impl_->withGl([&] {
        impl_->reads.clear();
        impl_->core.reset();
        return 0;
    });
}

Result<std::unique_ptr<Session>> Session::createHeadless(const Shadertoy& shadertoy, const SessionSettings& settings) {
    Result<std::unique_ptr<Impl>> impl = start(shadertoy, settings, /*headless=*/true);
    if (!impl) return impl.error();
    return std::unique_ptr<Session>(new Session(std::move(*impl)));
}

Result<std::unique_ptr<Session>> Session::createOnCurrentContext(const Shadertoy& shadertoy,
                                                                 const SessionSettings& settings) {
    Result<std::unique_ptr<Impl>> impl = start(shadertoy, settings, /*headless=*/false);
    if (!impl) return impl.error();
    return std::unique_ptr<Session>(new Session(std::move(*impl)));
}

namespace {
// The caller's events, checked as the CLI checks --mouse and the input scripts.
Status checkEvents(std::span<const InputEvent> events) {
    using T = InputEvent::Type;
    for (const InputEvent& e : events)
        if (Status ok = checkInputEventSetting(e.type == T::MouseDown || e.type == T::MouseMove, e.x, e.y,
                                               e.type == T::KeyDown || e.type == T::KeyUp, e.key);
            !ok)
            return ok;
    return okStatus();
}
}  // namespace

Status Session::step(std::span<const InputEvent> events) {
    if (Status given = checkEvents(events); !given) return given;
    std::vector<InputEvent>& all = impl_->events;
    all.clear();
    const FrameTime time = impl_->timeline->next(frame(), all);
    all.insert(all.end(), events.begin(), events.end());
    return impl_->render(time, all);
}

Status Session::stepAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> events) {
    if (Status clock = checkFrameClockSetting(time, timeDelta, frameRate); !clock) return clock;
    if (Status given = checkEvents(events); !given) return given;
    std::vector<InputEvent>& all = impl_->events;
    all.clear();
    impl_->timeline->eventsBefore(frame(), all);
    all.insert(all.end(), events.begin(), events.end());
    return impl_->render(impl_->timeline->atTime(time, timeDelta, frameRate), all);
}

double Session::timeOf(int n) const { return impl_->timeline->at(n).time; }

Status Session::Impl::render(const FrameTime& t, std::span<const InputEvent> events) {
    if (Status made = usable("step"); !made) return made;
    Status rendered = withGl([&] {
        Status drawn = core->renderFrame(t, events);
        // Submitted now, so that the GPU works on the frame while the caller goes on: a read that
        // follows waits less (llvmpipe would start the frame only when it is read: step(); frame()
        // on a trivial shader from Python, 1.18x the CLI's frame without this, 0.94-1.02x with it).
        glFlush();
        return drawn;
    });
    if (Status limit = expired(); !limit) return limit;
    return rendered;
}

Status Session::seek(int target) {
    if (Status made = impl_->usable("seek"); !made) return made;
    Status simulated = impl_->withGl([&] {
        Status done = impl_->core->seek(target, *impl_->timeline);
        glFlush();  // the buffers' frames drawn while the caller goes on, as step()'s
        return done;
    });
    if (Status limit = impl_->expired(); !limit) return limit;
    return simulated;
}

int Session::frame() const { return impl_->core->frame(); }
int Session::width() const { return impl_->core->width(); }
int Session::height() const { return impl_->core->height(); }

Status Session::setChannel(std::string_view name, int channel, const ChannelArray& pixels) {
    std::optional<PassId> pass = name == passName(PassId::CubeA) ? std::optional<PassId>(PassId::CubeA) : passNamed(name);
    if (!pass || !impl_->core->manifest().find(*pass))
        return Error("setChannel: no pass \"" + std::string(name) +
                         "\" (Image, or a buffer or Cube A the shadertoy has)",
                     Code::Usage);
    PixelArray array;
    array.width = pixels.width;
    array.height = pixels.height;
    array.components = pixels.components;
    array.type = pixels.type == ChannelArray::Type::UInt8 ? PixelType::UInt8 : PixelType::Float32;
    array.data = pixels.data;
    array.bytes = pixels.bytes;
    array.topRowFirst = pixels.order == RowOrder::TopFirst;
    SamplerDesc sampler;
    sampler.filter = pixels.filter == ChannelArray::Filter::Nearest  ? Filter::Nearest
                     : pixels.filter == ChannelArray::Filter::Linear ? Filter::Linear
                                                                     : Filter::Mipmap;
    sampler.wrap = pixels.wrap == ChannelArray::Wrap::Clamp ? Wrap::Clamp : Wrap::Repeat;
    if (Status made = impl_->usable("setChannel"); !made) return made;
    return impl_->withGl([&] { return impl_->core->setChannelArray(*pass, channel, array, sampler); });
}

Status Session::read(std::string_view name, std::span<std::uint8_t> out, RowOrder order) const {
    Result<PassId> pass = impl_->pass(name);
    if (!pass) return pass.error();
    const std::size_t values = static_cast<std::size_t>(width()) * height() * 4;
    if (out.size() != values)
        return Error("read: the destination holds " + std::to_string(out.size()) + " values, the frame " +
                         std::to_string(values) + " (width * height * 4)",
                     Code::Usage);
    if (Status usable = impl_->usable("read"); !usable) return usable;
    impl_->withGl([&] {
        impl_->core->readRgba8(*pass, impl_->bytes);
        return 0;
    });
    Impl::copyRows(impl_->bytes, out, width(), height(), order);
    return okStatus();
}

Status Session::read(std::string_view name, std::span<float> out, RowOrder order) const {
    Result<PassId> pass = impl_->pass(name);
    if (!pass) return pass.error();
    const std::size_t values = static_cast<std::size_t>(width()) * height() * 4;
    if (out.size() != values)
        return Error("read: the destination holds " + std::to_string(out.size()) + " values, the frame " +
                         std::to_string(values) + " (width * height * 4)",
                     Code::Usage);
    if (Status usable = impl_->usable("read"); !usable) return usable;
    impl_->withGl([&] {
        impl_->core->readRgba32f(*pass, impl_->floats);
        return 0;
    });
    Impl::copyRows(impl_->floats, out, width(), height(), order);
    return okStatus();
}

Result<Session::QueuedRead> Session::queueRead(std::string_view name) {
    Result<PassId> pass = impl_->pass(name);
    if (!pass) return pass.error();
    if (queuedReads() >= kMaxQueuedReads)
        return Error("queueRead: " + std::to_string(kMaxQueuedReads) + " reads wait already: take one first (takeRead)",
                     Code::Usage);
    if (Status usable = impl_->usable("queueRead"); !usable) return usable.error();
    const PassOutput output = impl_->core->output(*pass);
    const PendingReads::Read read{frame() - 1, output.width, output.height, output.format};
    Status started = impl_->withGl([&] { return impl_->reads.start(output.framebuffer, read); });
    if (!started) return started.error();
    return QueuedRead{read.frame, read.width, read.height};
}

int Session::queuedReads() const { return static_cast<int>(impl_->reads.size()); }

std::optional<Session::QueuedRead> Session::nextQueuedRead() const {
    if (impl_->reads.size() == 0) return std::nullopt;
    const PendingReads::Read& read = impl_->reads.oldest();
    return QueuedRead{read.frame, read.width, read.height};
}

bool Session::nextQueuedReadDone() const {
    if (impl_->reads.size() == 0 || !impl_->usable("nextQueuedReadDone")) return false;
    return impl_->withGl([&] { return impl_->reads.oldestDone(); });
}

Result<Session::QueuedRead> Session::takeRead(std::span<std::uint8_t> out, RowOrder order) {
    return impl_->takeRead(out, order);
}

Result<Session::QueuedRead> Session::takeRead(std::span<float> out, RowOrder order) {
    return impl_->takeRead(out, order);
}

void Session::dropQueuedReads() {
    if (impl_->reads.size() == 0 || !impl_->usable("dropQueuedReads")) return;
    impl_->withGl([&] {
        while (impl_->reads.size() > 0) (void)impl_->reads.releaseOldest();
        return 0;
    });
}

unsigned int Session::imageTexture() const { return impl_->core->output(PassId::Image).texture; }

Status Session::drawImage(unsigned int framebuffer, int x, int y, int w, int h) const {
    if (w <= 0 || h <= 0) return Error("drawImage: the size must be positive", Code::Usage);
    if (Status usable = impl_->usable("drawImage"); !usable) return usable;
    impl_->withGl([&] {
        const PassOutput image = impl_->core->output(PassId::Image);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, image.framebuffer);
        const bool same = w == image.width && h == image.height;
        glBlitFramebuffer(0, 0, image.width, image.height, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT,
                          same ? GL_NEAREST : GL_LINEAR);
        return 0;
    });
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("drawImage: ") + glErrorName(error), Code::GlSetup);
    return okStatus();
}

void Session::restart() {
    if (!impl_->usable("restart")) return;
    impl_->timeline->restart();
    impl_->withGl([&] {
        impl_->core->restart();
        return 0;
    });
}

Status Session::resize(int w, int h) {
    if (Status usable = impl_->usable("resize"); !usable) return usable;
    return impl_->withGl([&] { return impl_->core->resize(w, h); });
}

struct PreparedReload::Plan {
    const Session::Impl* session = nullptr;  // whose media settings planned it
    Result<PlayerPlan> plan;
};

PreparedReload::PreparedReload(std::unique_ptr<Plan> plan) : plan_(std::move(plan)) {}
PreparedReload::~PreparedReload() = default;
PreparedReload::PreparedReload(PreparedReload&&) noexcept = default;
PreparedReload& PreparedReload::operator=(PreparedReload&&) noexcept = default;

PreparedReload Session::prepareReload(const Shadertoy& next) const {
    // The media settings are fixed at creation: reading them races nothing the GL thread does.
    const MediaOptions& media = impl_->media;
    return PreparedReload(std::make_unique<PreparedReload::Plan>(PreparedReload::Plan{impl_.get(), planPlayer(ShadertoyAccess::desc(next), media, impl_->defines)}));
}

Result<Reloaded> Session::reload(PreparedReload prepared) {
    if (Status usable = impl_->usable("reload"); !usable) return usable.error();
    if (!prepared.plan_) return Error("reload: this PreparedReload was used already (or moved from)", Code::Usage);
    if (prepared.plan_->session != impl_.get())
        return Error("reload: the PreparedReload was made by another session's prepareReload", Code::Usage);
    ReloadOutcome outcome = impl_->withGl([&] { return impl_->core->reload({}, std::move(prepared.plan_->plan)); });
    prepared.plan_.reset();
    return Reloaded{outcome.applied, outcome.structureChanged, std::move(outcome.recompiled), std::move(outcome.problems)};
}

Result<Reloaded> Session::reload(const Shadertoy& next) { return reload(prepareReload(next)); }

Result<std::vector<float>> Session::renderSound(double seconds) {
    if (Status usable = impl_->usable("renderSound"); !usable) return usable.error();
    return impl_->withGl([&] { return impl_->core->renderSound(seconds); });
}

// --- render(): the frame stream over reads of the rendering's own ---------------------------------

// A rendering's reads as its FrameStream drives them: queued into pixel-pack buffers of their own,
// handed over mapped (RenderedFrame::read converts straight from them).
class Session::Rendering::Impl final : public FrameReads {
public:
    Impl(Session& session, RenderRequest request, PassId pass)
        : session(session),
          s(*session.impl_),
          request(std::move(request)),
          pass(pass),
          stream(FrameStreamSettings{this->request.frames, this->request.every, kRenderReadsInFlight, session.frame()}),
          reads(&s.context->gpuActivity()) {}

    Session& session;
    Session::Impl& s;
    const RenderRequest request;
    const PassId pass;
    FrameStream stream;
    PendingReads reads;
    int rendered = 0;
    const FrameCallback* onFrame = nullptr;  // advance()'s, while it runs
    // Frames submitted and not yet drawn, oldest first. A GPU (llvmpipe above all) takes dozens of
    // frames before it makes the submitter wait: the counter would run that far ahead of the
    // pictures, and a stop would leave that much drawing to finish. Two keep it busy.
    static constexpr std::size_t kFramesAhead = 2;
    std::deque<GlFence> drawing;

    // Waits until fewer than kFramesAhead frames are being drawn (the context current).
    Status pace() {
        while (drawing.size() >= kFramesAhead) {
            GLenum state;
            {
                // The wait is for the GPU drawing: the watchdog is told which pass.
                GpuActivity::Wait wait(&s.context->gpuActivity());
                state = glClientWaitSync(drawing.front().get(), GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
            }
            if (state == GL_WAIT_FAILED)
                return Error(std::string("GL: waiting for a frame to be drawn failed: ") + glErrorName(glGetError()),
                             Code::GlReadback);
            if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) drawing.pop_front();
        }
        return okStatus();
    }

    int pending() const override { return static_cast<int>(reads.size()); }
    Status start(int) override {
        const PassOutput output = s.core->output(pass);
        return reads.start(output.framebuffer, {session.frame() - 1, output.width, output.height, output.format});
    }
    bool oldestDone() const override { return reads.oldestDone(); }
    Status handOverOldest() override {
        const PendingReads::Read read = reads.oldest();
        // mapOldest() tells the watchdog which pass the GPU is still drawing while it waits.
        Result<std::span<const std::byte>> pixels = reads.mapOldest();
        if (!pixels) {
            (void)reads.releaseOldest();
            return pixels.error();
        }
        RenderedFrame frame;
        frame.frame = read.frame;
        frame.width = read.width;
        frame.height = read.height;
        frame.pixels_ = pixels->data();
        frame.floatPixels_ = read.format != PixelFormat::Rgba8;
        bool goOn = false;
        try {
            goOn = (*onFrame)(frame);
        } catch (...) {
            (void)reads.releaseOldest();  // unmapped before the caller's exception leaves
            throw;
        }
        if (!goOn) stream.requestStop();
        return reads.releaseOldest();
    }
    void dropAll() override { reads.clear(); }

    void drop() {
        if ((reads.size() == 0 && drawing.empty()) || !s.onOwnThread() || !s.current()) return;
        s.withGl([&] {
            reads.clear();
            drawing.clear();
            return 0;
        });
    }
};

Session::Rendering::Rendering(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Session::Rendering::~Rendering() {
    if (!impl_) return;
    impl_->drop();
    // Off the session's thread its GL buffers cannot be deleted there (no context): forgotten.
    if (!impl_->s.onOwnThread()) {
        impl_->reads.clear();
        impl_->drawing.clear();
    }
}

Result<bool> Session::Rendering::advance(const FrameCallback& onFrame) {
    Impl& r = *impl_;
    if (Status usable = r.s.usable("advance"); !usable) return usable.error();
    if (r.stream.stopRequested()) {
        r.drop();
        return false;
    }
    r.onFrame = &onFrame;
    Status done = okStatus();
    if (r.rendered < r.request.frames) {
        std::span<const InputEvent> events;
        if (r.rendered == 0) events = r.request.events;
        done = r.s.withGl([&] { return r.pace(); });
        if (done) done = r.session.step(events);
        if (done) {
            const int index = r.rendered++;
            done = r.s.withGl([&] {
                r.drawing.emplace_back(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
                return r.stream.rendered(index, r);
            });
        }
    }
    if (done && r.rendered >= r.request.frames) done = r.s.withGl([&] { return r.stream.finish(r); });
    r.onFrame = nullptr;
    if (Status limit = r.s.expired(); !limit && done) done = limit;
    if (!done) {
        r.drop();
        return done.error();
    }
    if (r.stream.stopRequested()) {
        r.drop();
        return false;
    }
    return r.rendered < r.request.frames || r.reads.size() > 0;
}

void Session::Rendering::stop() { impl_->stream.requestStop(); }
int Session::Rendering::framesRendered() const { return impl_->rendered; }
int Session::Rendering::readsInFlight() const { return static_cast<int>(impl_->reads.size()); }

Result<std::unique_ptr<Session::Rendering>> Session::startRendering(const RenderRequest& request) {
    if (Status usable = impl_->usable("startRendering"); !usable) return usable.error();
    if (Status given = checkEvents(request.events); !given) return given.error();
    if (request.frames < 0)
        return Error("render: frames must be 0 or more, got " + std::to_string(request.frames), Code::Usage);
    if (request.every < 1)
        return Error("render: every must be 1 or more, got " + std::to_string(request.every), Code::Usage);
    Result<PassId> pass = impl_->pass(request.pass);
    if (!pass) return pass.error();
    auto impl = std::make_unique<Rendering::Impl>(*this, request, *pass);
    // The reads' buffers now, at the pass's size: a failure to allocate them shows here.
    const PassOutput output = impl_->core->output(*pass);
    Status reserved = impl_->withGl([&] {
        return impl->reads.reserve(frameBytes(output.width, output.height, output.format),
                                   static_cast<std::size_t>(kRenderReadsInFlight));
    });
    if (!reserved) return reserved.error();
    return std::unique_ptr<Rendering>(new Rendering(std::move(impl)));
}

namespace {
// The recording checks are the CLI's, whose messages name its flag ("--out f.png: ..."); a
// library or Python caller gave RecordRequest::out, so the message names that field instead.
Error namingOutField(Error error) {
    constexpr std::string_view flag = "--out ";
    for (Diagnostic& d : error.diagnostics)
        if (std::string_view(d.message).substr(0, flag.size()) == flag) {
            d.message = "out: " + d.message.substr(flag.size());
            if (d.field.empty()) d.field = "out";
        }
    return error;
}
}  // namespace

Result<std::vector<std::string>> Session::record(const RecordRequest& request) {
    if (Status usable = impl_->usable("record"); !usable) return usable.error();
    if (Status given = checkEvents(request.events); !given) return given.error();
    Result<PassId> pass = impl_->pass(request.pass);
    if (!pass) return pass.error();
    Result<SessionPlan> plan = planRecording(impl_->core->plan(), request.out, request.frames, request.every, *pass);
    if (!plan) return namingOutField(plan.error());
    Status begun = impl_->withGl([&] { return impl_->core->beginRecording(std::move(*plan)); });
    if (!begun) return namingOutField(begun.error());
    Status rendered = okStatus();
    for (int n = 0; n < request.frames && rendered; ++n) {
        std::vector<InputEvent>& all = impl_->events;
        all.clear();
        const FrameTime time = impl_->timeline->next(frame(), all);
        if (n == 0) all.insert(all.end(), request.events.begin(), request.events.end());
        rendered = impl_->render(time, all);
    }
    if (!rendered) {
        impl_->withGl([&] { (void)impl_->core->abandonRecording(); });
        return rendered.error();
    }
    Result<std::vector<std::filesystem::path>> files = impl_->withGl([&] { return impl_->core->endRecording(); });
    if (!files) return files.error();
    std::vector<std::string> names;
    for (const std::filesystem::path& file : *files) names.push_back(file.string());
    return names;
}

Status Session::render(const RenderRequest& request, const FrameCallback& onFrame) {
    Result<std::unique_ptr<Rendering>> rendering = startRendering(request);
    if (!rendering) return rendering.error();
    for (;;) {
        Result<bool> more = (*rendering)->advance(onFrame);
        if (!more) return more.error();
        if (!*more) return okStatus();
    }
}

namespace {
template <class T>
Status readRendered(const void* pixels, bool floatPixels, int width, int height, std::span<T> out, RowOrder order) {
    const std::size_t values = static_cast<std::size_t>(width) * height * 4;
    if (!pixels) return Error("RenderedFrame::read: the frame's pixels are gone (read it during the callback)", Code::Usage);
    if (out.size() != values)
        return Error("RenderedFrame::read: the destination holds " + std::to_string(out.size()) + " values, the frame " +
                         std::to_string(values) + " (width * height * 4)",
                     Code::Usage);
    if (floatPixels) Session::Impl::convertRows(static_cast<const float*>(pixels), out, width, height, order);
    else Session::Impl::convertRows(static_cast<const std::uint8_t*>(pixels), out, width, height, order);
    return okStatus();
}
}  // namespace

Status Session::RenderedFrame::read(std::span<std::uint8_t> out, RowOrder order) const {
    return readRendered(pixels_, floatPixels_, width, height, out, order);
}

Status Session::RenderedFrame::read(std::span<float> out, RowOrder order) const {
    return readRendered(pixels_, floatPixels_, width, height, out, order);
}

const std::vector<Diagnostic>& Session::notices() const { return impl_->notices.kept; }

std::string Session::backend() const { return impl_->context->describe(); }

void setWatchdogExpiryHandler(std::function<void(const Diagnostic&)> handler) {
    std::lock_guard<std::mutex> lock(expiryMutex);
    expiryHandler() = std::move(handler);
}

}  // namespace toyhost
