#include <toyhost/Session.h>

#include <GLES3/gl3.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <optional>
#include <type_traits>

#include "api/ShadertoyAccess.h"
#include "gl/CurrentContext.h"
#include "gl/GlStateGuard.h"
#include "gl/GlThread.h"
#include "gl/HeadlessContext.h"
#include "image/PixelConversion.h"
#include "manifest/ManifestDesc.h"
#include "render/PendingReads.h"
#include "session/SessionCore.h"
#include "timing/FrameClock.h"

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
    std::optional<FrameClock> clock;
    mutable std::vector<std::uint8_t> bytes;  // readback scratch
    mutable std::vector<float> floats;
    PendingReads reads;  // queueRead() .. takeRead(); emptied with the context current

    // What every call that renders does around its GL work: the context current (headless) or the
    // caller's state kept (its own context).
    template <class Work>
    auto withGl(Work work) const {
        if (ownContext) {
            (void)context->makeCurrent();
            return work();
        }
        GlStateGuard guard;
        return work();
    }
    // The context usable here (a headless session's is made current on this thread; it fails when
    // another thread holds it).
    Status current() const { return ownContext ? context->makeCurrent() : okStatus(); }
    // A limit that passed while the call ran.
    Status expired() const {
        if (watchdog)
            if (std::optional<Diagnostic> d = watchdog->expired()) return Error(*d);
        return okStatus();
    }
    Result<PassId> pass(std::string_view name) const {
        std::optional<PassId> id = passNamed(name);
        if (!id || !core->player().manifest().find(*id))
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
        if (Status made = current(); !made) return made.error();
        Status taken = withGl([&] {
            // The wait may be for the GPU still drawing: the watchdog is told which pass.
            core->player().publishPendingDraws();
            Result<std::span<const std::byte>> pixels = reads.mapOldest();
            core->player().publishPendingDraws();
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
    if (settings.width || settings.height) {
        options.width = settings.width;
        options.height = settings.height;
    }
    if (settings.fps > 0) options.fps = settings.fps;
    options.startTime = settings.startTime;
    if (!settings.date.empty()) {
        Result<double> wallClock = parseWallClock(settings.date);
        if (!wallClock) return Error("date: " + wallClock.error().first().message, Code::Usage);
        options.wallClock = *wallClock;
    }
    options.media.folders = settings.mediaFolders;
    for (const auto& [id, file] : settings.mediaFiles) options.media.files.emplace_back(id, file);
    options.floatImage = settings.floatImage;
    options.frameTimeout = settings.frameTimeout;
    options.compileTimeout = settings.compileTimeout;
    Result<SessionPlan> plan = prepareSession(options);
    if (!plan) return plan.error();
    impl->clock.emplace(*plan->options.fps, plan->options.startTime, *plan->options.wallClock);
    if (settings.frameTimeout > 0 || settings.compileTimeout > 0) {
        WatchdogDesc limits;
        limits.frameLimit = settings.frameTimeout;
        limits.compileLimit = settings.compileTimeout;
        limits.expire = [file = shadertoy.path().string()](const Diagnostic& expired, int) {
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
        impl->watchdog = std::make_unique<Watchdog>(limits);
    }
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

Status Session::step(std::span<const InputEvent> events) {
    return stepAt(impl_->clock->time(frame()), impl_->clock->timeDelta(), impl_->clock->fps(), events);
}

Status Session::stepAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> events) {
    if (Status current = impl_->current(); !current) return current;
    FrameTime t{time, timeDelta, frameRate, impl_->clock->date(0)};
    // iDate follows iTime from the date of time 0 (FrameClock's form).
    t.date = dateAt(*impl_->core->plan().options.wallClock + (time - impl_->core->plan().options.startTime));
    Status rendered = impl_->withGl([&] {
        Status drawn = impl_->core->renderFrame(t, events);
        // Submitted now, so that the GPU works on the frame while the caller goes on: a read that
        // follows waits less (llvmpipe would start the frame only when it is read: step(); frame()
        // on a trivial shader from Python, 1.18x the CLI's frame without this, 0.94-1.02x with it).
        glFlush();
        return drawn;
    });
    if (Status limit = impl_->expired(); !limit) return limit;
    return rendered;
}

int Session::frame() const { return impl_->core->player().frame(); }
int Session::width() const { return impl_->core->player().width(); }
int Session::height() const { return impl_->core->player().height(); }

Status Session::read(std::string_view name, std::span<std::uint8_t> out, RowOrder order) const {
    Result<PassId> pass = impl_->pass(name);
    if (!pass) return pass.error();
    const std::size_t values = static_cast<std::size_t>(width()) * height() * 4;
    if (out.size() != values)
        return Error("read: the destination holds " + std::to_string(out.size()) + " values, the frame " +
                         std::to_string(values) + " (width * height * 4)",
                     Code::Usage);
    if (Status current = impl_->current(); !current) return current;
    impl_->withGl([&] {
        impl_->core->player().readRgba8(*pass, impl_->bytes);
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
    if (Status current = impl_->current(); !current) return current;
    impl_->withGl([&] {
        impl_->core->player().readRgba32f(*pass, impl_->floats);
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
    if (Status current = impl_->current(); !current) return current.error();
    const PassOutput output = impl_->core->player().output(*pass);
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
    if (impl_->reads.size() == 0 || !impl_->current()) return false;
    return impl_->withGl([&] { return impl_->reads.oldestDone(); });
}

Result<Session::QueuedRead> Session::takeRead(std::span<std::uint8_t> out, RowOrder order) {
    return impl_->takeRead(out, order);
}

Result<Session::QueuedRead> Session::takeRead(std::span<float> out, RowOrder order) {
    return impl_->takeRead(out, order);
}

void Session::dropQueuedReads() {
    if (impl_->reads.size() == 0 || !impl_->current()) return;
    impl_->withGl([&] {
        while (impl_->reads.size() > 0) (void)impl_->reads.releaseOldest();
        return 0;
    });
}

unsigned int Session::imageTexture() const { return impl_->core->player().output(PassId::Image).texture; }

Status Session::drawImage(unsigned int framebuffer, int x, int y, int w, int h) const {
    if (w <= 0 || h <= 0) return Error("drawImage: the size must be positive", Code::Usage);
    if (Status current = impl_->current(); !current) return current;
    impl_->withGl([&] {
        const PassOutput image = impl_->core->player().output(PassId::Image);
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
    impl_->withGl([&] {
        impl_->core->restart();
        return 0;
    });
}

Status Session::resize(int w, int h) {
    if (Status current = impl_->current(); !current) return current;
    return impl_->withGl([&] { return impl_->core->resize(w, h); });
}

Result<Reloaded> Session::reload(const Shadertoy& next) {
    Result<PlayerPlan> plan = planPlayer(ShadertoyAccess::desc(next), impl_->core->plan().options.media);
    ReloadOutcome outcome = impl_->withGl([&] { return impl_->core->reload(std::move(plan)); });
    return Reloaded{outcome.applied, outcome.structureChanged, std::move(outcome.recompiled), std::move(outcome.problems)};
}

Result<std::vector<float>> Session::renderSound(double seconds) {
    return impl_->withGl([&] { return impl_->core->renderSound(seconds); });
}

const std::vector<Diagnostic>& Session::notices() const { return impl_->notices.kept; }

std::string Session::backend() const { return impl_->context->describe(); }

void setWatchdogExpiryHandler(std::function<void(const Diagnostic&)> handler) {
    std::lock_guard<std::mutex> lock(expiryMutex);
    expiryHandler() = std::move(handler);
}

}  // namespace toyhost
