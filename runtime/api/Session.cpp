// The library's Session (include/toyhost/Session.h) over the session layer: a SessionCore on a
// headless or the caller's context, its calls checked and run with the context current; frames
// into memory through session/MemoryFrameStream.h. No GL call of its own.
#include <toyhost/Session.h>

#include <optional>

#include "api/ShadertoyAccess.h"
#include "core/Defaults.h"
#include "image/PixelConversion.h"
#include "manifest/ManifestDesc.h"
#include "session/HostedSession.h"
#include "session/MemoryFrameStream.h"
#include "session/WatchdogSetup.h"
#include "session/SettingChecks.h"

namespace toyhost {

namespace {

std::optional<PassId> passNamed(std::string_view name) {
    for (PassId id : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD, PassId::Image})
        if (name == passName(id)) return id;
    return std::nullopt;
}

// `out`'s size against a frame's width * height * 4 values.
Status checkDestination(const char* call, std::size_t size, int width, int height) {
    const std::size_t values = static_cast<std::size_t>(width) * height * 4;
    if (size == values) return okStatus();
    return Error(std::string(call) + ": the destination holds " + std::to_string(size) + " values, the frame " +
                     std::to_string(values) + " (width * height * 4)",
                 Code::Usage);
}

}  // namespace

// The session as the library hosts it (session/HostedSession.h), with what only the API needs.
class Session::Impl final : public HostedSession {
public:
    static Result<std::unique_ptr<Session>> create(const Shadertoy& shadertoy, const SessionSettings& settings,
                                                   Context context);
    Result<PassId> pass(std::string_view name) const {
        std::optional<PassId> id = passNamed(name);
        if (!id || !core().manifest().find(*id))
            return Error("no pass \"" + std::string(name) + "\" to read (Image, or a buffer the shadertoy has)",
                         Code::Usage);
        return *id;
    }
    template <class T>
    Status read(std::string_view name, std::span<T> out, RowOrder order) const {
        Result<PassId> id = pass(name);
        if (!id) return id.error();
        if (Status fits = checkDestination("read", out.size(), core().width(), core().height()); !fits) return fits;
        if (Status made = usable("read"); !made) return made;
        readPass(*id, out, order == RowOrder::TopFirst);
        return okStatus();
    }
};

Result<std::unique_ptr<Session>> Session::Impl::create(const Shadertoy& shadertoy, const SessionSettings& settings,
                                                      Context context) {
    SessionOptions options;
    options.shadertoy = std::make_shared<const ManifestDesc>(ShadertoyAccess::desc(shadertoy));
    options.target = shadertoy.path();
    // The caller's settings as given: prepareSession checks what was given (width 0 is refused as
    // `run --size 0x0` is) and fills what was not, as for a run.
    options.settings = settings;
    options.framesInMemory = true;  // read by the caller: drawn whole, never in tiles
    // A Session has no watchdog limits unless its settings give them (the commands have theirs).
    if (!options.settings.frameTimeout) options.settings.frameTimeout = defaults::kSessionTimeoutSeconds;
    if (!options.settings.compileTimeout) options.settings.compileTimeout = defaults::kSessionTimeoutSeconds;
    auto impl = std::make_unique<Impl>();
    if (Status started = impl->start(std::move(options), context); !started) return started.error();
    return std::unique_ptr<Session>(new Session(std::move(impl)));
}

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Session::~Session() = default;

Result<std::unique_ptr<Session>> Session::createHeadless(const Shadertoy& shadertoy, const SessionSettings& settings) {
    return Impl::create(shadertoy, settings, HostedSession::Context::Headless);
}

Result<std::unique_ptr<Session>> Session::createOnCurrentContext(const Shadertoy& shadertoy,
                                                                 const SessionSettings& settings) {
    return Impl::create(shadertoy, settings, HostedSession::Context::Current);
}

Status Session::step(std::span<const InputEvent> events) {
    if (Status given = HostedSession::checkEvents(events); !given) return given;
    return impl_->render("step", [&] { return impl_->next(events); });
}

Status Session::stepAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> events) {
    if (Status clock = checkFrameClockSetting(time, timeDelta, frameRate); !clock) return clock;
    if (Status given = HostedSession::checkEvents(events); !given) return given;
    return impl_->render("step", [&] { return impl_->nextAt(time, timeDelta, frameRate, events); });
}

double Session::timeOf(int n) const { return impl_->timeline().at(n).time; }

int Session::frame() const { return impl_->core().frame(); }
int Session::width() const { return impl_->core().width(); }
int Session::height() const { return impl_->core().height(); }

Status Session::seek(int target) {
    return impl_->render("seek", [&] {
        Status done = impl_->core().seek(target, impl_->timeline());
        impl_->core().submit();  // the buffers' frames drawn while the caller goes on, as step()'s
        return done;
    });
}

Status Session::setChannel(std::string_view name, int channel, const ChannelArray& pixels) {
    std::optional<PassId> pass = name == passName(PassId::CubeA) ? std::optional<PassId>(PassId::CubeA) : passNamed(name);
    if (!pass || !impl_->core().manifest().find(*pass))
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
    return impl_->withGl([&] { return impl_->core().setChannelArray(*pass, channel, array, sampler); });
}

Status Session::read(std::string_view name, std::span<std::uint8_t> out, RowOrder order) const {
    return impl_->read(name, out, order);
}

Status Session::read(std::string_view name, std::span<float> out, RowOrder order) const {
    return impl_->read(name, out, order);
}

unsigned int Session::imageTexture() const { return impl_->core().output(PassId::Image).texture; }

Status Session::drawImage(unsigned int framebuffer, int x, int y, int w, int h) const {
    if (w <= 0 || h <= 0) return Error("drawImage: the size must be positive", Code::Usage);
    if (Status usable = impl_->usable("drawImage"); !usable) return usable;
    Status drawn = impl_->withGl([&] { return impl_->core().drawImage(framebuffer, x, y, w, h); });
    if (!drawn) return Error("drawImage: " + drawn.error().first().message, Code::GlSetup);
    return okStatus();
}

void Session::restart() {
    if (!impl_->usable("restart")) return;
    impl_->timeline().restart();
    impl_->withGl([&] {
        impl_->core().restart();
        return 0;
    });
}

Status Session::resize(int w, int h) {
    if (Status usable = impl_->usable("resize"); !usable) return usable;
    return impl_->withGl([&] { return impl_->core().resize(w, h); });
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
    const MediaOptions& media = impl_->media();
    return PreparedReload(std::make_unique<PreparedReload::Plan>(PreparedReload::Plan{impl_.get(), planPlayer(ShadertoyAccess::desc(next), media, impl_->defines())}));
}

Result<Reloaded> Session::reload(PreparedReload prepared) {
    if (Status usable = impl_->usable("reload"); !usable) return usable.error();
    if (!prepared.plan_) return Error("reload: this PreparedReload was used already (or moved from)", Code::Usage);
    if (prepared.plan_->session != impl_.get())
        return Error("reload: the PreparedReload was made by another session's prepareReload", Code::Usage);
    ReloadOutcome outcome = impl_->withGl([&] { return impl_->core().reload({}, std::move(prepared.plan_->plan)); });
    prepared.plan_.reset();
    return Reloaded{outcome.applied, outcome.structureChanged, std::move(outcome.recompiled), std::move(outcome.problems)};
}

Result<Reloaded> Session::reload(const Shadertoy& next) { return reload(prepareReload(next)); }

Result<std::vector<float>> Session::renderSound(double seconds) {
    if (Status usable = impl_->usable("renderSound"); !usable) return usable.error();
    return impl_->withGl([&] { return impl_->core().renderSound(seconds); });
}

// --- render(): the memory frame stream, its frames stepped by step() ---------------------------------

class Session::Rendering::Impl {
public:
    Session::Impl& s;
    std::vector<InputEvent> events;  // before the first frame
    std::unique_ptr<MemoryFrameStream> stream;

    // Reads and fences dropped (after an error), on the session's thread with its context.
    void drop() {
        if (!stream->holdsGl() || !s.onOwnThread() || !s.current()) return;
        s.withGl([&] {
            stream->drop();
            return 0;
        });
    }
};

Session::Rendering::Rendering(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Session::Rendering::~Rendering() {
    if (!impl_) return;
    Impl& r = *impl_;
    // Its GL objects go on the session's thread, with the context; off it they cannot be deleted
    // there (no context): forgotten.
    if (r.s.onOwnThread() && r.s.current())
        r.s.withGl([&] {
            r.stream.reset();
            return 0;
        });
    else r.stream->drop();
}

Result<bool> Session::Rendering::advance(const FrameCallback& onFrame) {
    Impl& r = *impl_;
    if (Status usable = r.s.usable("advance"); !usable) return usable.error();
    auto step = [&](int index) {
        Status drawn = r.s.next(index == 0 ? std::span<const InputEvent>(r.events) : std::span<const InputEvent>());
        if (Status limit = r.s.expired(); !limit) return limit;
        return drawn;
    };
    auto take = [&](const MemoryFrame& read) {
        RenderedFrame frame;
        frame.frame = read.frame;
        frame.width = read.width;
        frame.height = read.height;
        frame.pixels_ = read.pixels;
        frame.floatPixels_ = read.format != PixelFormat::Rgba8;
        return onFrame(frame);
    };
    Result<bool> more = r.s.withGl([&] { return r.stream->advance(step, take); });
    if (Status limit = r.s.expired(); !limit && more) more = limit.error();
    if (!more) r.drop();
    return more;
}

void Session::Rendering::stop() { impl_->stream->requestStop(); }
int Session::Rendering::framesRendered() const { return impl_->stream->framesRendered(); }
int Session::Rendering::readsInFlight() const { return impl_->stream->readsInFlight(); }

Result<std::unique_ptr<Session::Rendering>> Session::startRendering(const RenderRequest& request) {
    if (Status usable = impl_->usable("startRendering"); !usable) return usable.error();
    if (Status given = HostedSession::checkEvents(request.events); !given) return given.error();
    if (request.frames < 0)
        return Error("render: frames must be 0 or more, got " + std::to_string(request.frames), Code::Usage);
    if (request.every < 1)
        return Error("render: every must be 1 or more, got " + std::to_string(request.every), Code::Usage);
    Result<PassId> pass = impl_->pass(request.pass);
    if (!pass) return pass.error();
    const MemoryStreamRequest wanted{request.frames, request.every, *pass, kRenderReadsInFlight, frame()};
    Result<std::unique_ptr<MemoryFrameStream>> stream =
        impl_->withGl([&] { return MemoryFrameStream::open(impl_->core(), wanted); });
    if (!stream) return stream.error();
    return std::unique_ptr<Rendering>(
        new Rendering(std::unique_ptr<Rendering::Impl>(new Rendering::Impl{*impl_, request.events, std::move(*stream)})));
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
    if (Status given = HostedSession::checkEvents(request.events); !given) return given.error();
    Result<PassId> pass = impl_->pass(request.pass);
    if (!pass) return pass.error();
    Result<SessionPlan> plan = planRecording(impl_->core().plan(), request.out, request.frames, request.every, *pass);
    if (!plan) return namingOutField(plan.error());
    Status begun = impl_->withGl([&] { return impl_->core().beginRecording(std::move(*plan)); });
    if (!begun) return namingOutField(begun.error());
    Status rendered = okStatus();
    for (int n = 0; n < request.frames && rendered; ++n)
        rendered = step(n == 0 ? std::span<const InputEvent>(request.events) : std::span<const InputEvent>());
    if (!rendered) {
        impl_->withGl([&] { (void)impl_->core().abandonRecording(); });
        return rendered.error();
    }
    Result<std::vector<std::filesystem::path>> files = impl_->withGl([&] { return impl_->core().endRecording(); });
    if (!files) return files.error();
    std::vector<std::string> names;
    for (const std::filesystem::path& file : *files) names.push_back(file.string());
    return names;
}

namespace {
template <class T>
Status readRendered(const void* pixels, bool floatPixels, int width, int height, std::span<T> out, RowOrder order) {
    if (!pixels) return Error("RenderedFrame::read: the frame's pixels are gone (read it during the callback)", Code::Usage);
    if (Status fits = checkDestination("RenderedFrame::read", out.size(), width, height); !fits) return fits;
    if (floatPixels) convertRgbaRows(static_cast<const float*>(pixels), out, width, height, order == RowOrder::TopFirst);
    else convertRgbaRows(static_cast<const std::uint8_t*>(pixels), out, width, height, order == RowOrder::TopFirst);
    return okStatus();
}
}  // namespace

Status Session::RenderedFrame::read(std::span<std::uint8_t> out, RowOrder order) const {
    return readRendered(pixels_, floatPixels_, width, height, out, order);
}

Status Session::RenderedFrame::read(std::span<float> out, RowOrder order) const {
    return readRendered(pixels_, floatPixels_, width, height, out, order);
}

const std::vector<Diagnostic>& Session::notices() const { return impl_->notices(); }

std::string Session::backend() const { return impl_->context().describe(); }

void setWatchdogExpiryHandler(std::function<void(const Diagnostic&)> handler) {
    setLibraryExpiryHandler(std::move(handler));
}

}  // namespace toyhost
