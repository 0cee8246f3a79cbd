// The native session: toyhost::Session created, used and destroyed on a GlWorker. Python arguments
// are converted while the GIL is held; the GL work runs with it released.
#include "SessionBinding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <cstdint>
#include <unistd.h>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <toyhost/Session.h>

#include "Errors.h"
#include "Gil.h"
#include "GlWorker.h"
#include "PythonFrameStream.h"
#include "Signals.h"

namespace py = pybind11;

namespace toyhost::python {

namespace {

// Sessions open in this process, and which process that is. A fork() copies the driver's state
// (EGL, llvmpipe) but not its threads, so a child of a process with a session open cannot start GL
// at all (Mesa waits forever for threads that are not there); with none open, the display was
// released and the child starts afresh. Changed with the GIL held (or at a close, atomically).
std::atomic<int> openSessions{0};
int openSessionsProcess = 0;

}  // namespace

void refuseAfterForkWithGlOpen() {
    if (openSessions.load() > 0 && openSessionsProcess != static_cast<int>(::getpid()))
        throw ToyhostError(Error("this process was forked while a session was open in its parent, and GL cannot start "
                                 "in such a child: close every session before forking, or start workers with "
                                 "multiprocessing's \"spawn\" or \"forkserver\" method",
                                 Code::Usage));
}

namespace {

class NativeSession {
public:
    NativeSession(const Shadertoy& shadertoy, const SessionSettings& settings) {
        refuseAfterForkWithGlOpen();
        session_ = valueOrThrow(onGlThread([&] { return Session::createHeadless(shadertoy, settings); }));
        openSessionsProcess = static_cast<int>(::getpid());
        ++openSessions;
        width_ = session_->width();
        height_ = session_->height();
    }
    ~NativeSession() { close(); }
    NativeSession(const NativeSession&) = delete;
    NativeSession& operator=(const NativeSession&) = delete;

    // The session's GL objects and context go now, on the worker (idempotent).
    void close() {
        if (!session_) return;
        if (!worker_.inOwnProcess()) {
            // A forked child's copy: its GL objects are the parent's to free; forget them here.
            (void)session_.release();
            return;
        }
        // Frames being rendered ahead stop first (their jobs never touch the session after this);
        // a loop still taking them raises, whatever thread closed the session and when.
        for (std::weak_ptr<PythonFrameStream>& stream : streams_)
            if (std::shared_ptr<PythonFrameStream> alive = stream.lock())
                alive->cancel(Error("the session was closed while render() ran", Code::Usage));
        streams_.clear();
        // A destructor may run without the GIL held (interpreter shutdown); release only when held.
        // Then the thread goes too (joined: its 1 GiB stack with it), not at garbage collection.
        if (PyGILState_Check()) withoutGil([&] { stopAfter(); });
        else stopAfter();
        --openSessions;
    }
    bool closed() const { return !session_; }

    // Renders the next frame; returns its iFrame.
    int step(const std::vector<InputEvent>& events, std::optional<double> time, double timeDelta, double frameRate) {
        Session& s = open();
        return onGlThread([&] {
            const int index = s.frame();
            throwIfFailed(time ? s.stepAt(*time, timeDelta, frameRate, events) : s.step(events));
            return index;
        });
    }

    // Simulates the frames before iFrame `frame` without reading anything back (Session::seek).
    void seek(int frame) {
        Session& s = open();
        throwIfFailed(onGlThread([&] { return s.seek(frame); }));
    }

    // render(): frames rendered ahead on the worker, taken by PythonFrameStream.next().
    std::shared_ptr<PythonFrameStream> render(std::vector<InputEvent> events, int frames, int every, const std::string& pass,
                                         bool floats) {
        Session& s = open();
        std::erase_if(streams_, [](const std::weak_ptr<PythonFrameStream>& stream) { return stream.expired(); });
        RenderRequest request{Session::RenderRequest{frames, every, pass, std::move(events)}, floats};
        std::shared_ptr<PythonFrameStream> stream = PythonFrameStream::start(worker_, s, std::move(request));
        streams_.push_back(stream);
        return stream;
    }

    template <class T>
    py::array_t<T> read(const std::string& pass) {
        Session& s = open();
        py::array_t<T> pixels({height_, width_, 4});
        std::span<T> out(pixels.mutable_data(), static_cast<std::size_t>(pixels.size()));
        throwIfFailed(onGlThread([&] { return s.read(pass, out, RowOrder::TopFirst); }));
        return pixels;
    }

    // read() into the caller's array (reused from frame to frame): C-contiguous, writeable,
    // (height, width, 4) of T.
    template <class T>
    py::array readInto(const std::string& pass, py::array out) {
        Session& s = open();
        const bool fits = out.ndim() == 3 && out.shape(0) == height_ && out.shape(1) == width_ && out.shape(2) == 4 &&
                          out.dtype().is(py::dtype::of<T>()) && (out.flags() & py::array::c_style) && out.writeable();
        if (!fits)
            throw ToyhostError(Error("out: expected a writeable C-contiguous " + std::string(py::str(py::dtype::of<T>())) +
                                         " array of shape (" + std::to_string(height_) + ", " + std::to_string(width_) +
                                         ", 4)",
                                     Code::Usage));
        std::span<T> values(static_cast<T*>(out.mutable_data()), static_cast<std::size_t>(out.size()));
        throwIfFailed(onGlThread([&] { return s.read(pass, values, RowOrder::TopFirst); }));
        return out;
    }

    // Session.set_channel(): the array's memory uploaded straight from numpy on the GL thread (the
    // caller's thread waits, holding the array) after the Python side checked dtype and layout.
    void setChannel(const std::string& pass, int channel, const py::array& pixels, const std::string& filter,
                    const std::string& wrap) {
        Session& s = open();
        const bool bytes = pixels.dtype().is(py::dtype::of<std::uint8_t>());
        const bool floats = pixels.dtype().is(py::dtype::of<float>());
        if ((!bytes && !floats) || (pixels.ndim() != 2 && pixels.ndim() != 3) || !(pixels.flags() & py::array::c_style))
            throw ToyhostError(Error("array: expected a C-contiguous uint8 or float32 array of shape (height, width) "
                                     "or (height, width, 1|3|4)",
                                     Code::Usage));
        ChannelArray array;
        array.height = static_cast<int>(std::min<py::ssize_t>(pixels.shape(0), INT32_MAX));
        array.width = static_cast<int>(std::min<py::ssize_t>(pixels.shape(1), INT32_MAX));
        array.components = pixels.ndim() == 3 ? static_cast<int>(std::min<py::ssize_t>(pixels.shape(2), 16)) : 1;
        array.type = bytes ? ChannelArray::Type::UInt8 : ChannelArray::Type::Float32;
        array.data = pixels.data();
        array.bytes = static_cast<std::size_t>(pixels.nbytes());
        array.order = RowOrder::TopFirst;
        array.filter = filter == "nearest" ? ChannelArray::Filter::Nearest
                       : filter == "mipmap" ? ChannelArray::Filter::Mipmap
                                            : ChannelArray::Filter::Linear;
        array.wrap = wrap == "repeat" ? ChannelArray::Wrap::Repeat : ChannelArray::Wrap::Clamp;
        throwIfFailed(onGlThread([&] { return s.setChannel(pass, channel, array); }));
    }

    py::array_t<float> renderSound(double seconds) {
        Session& s = open();
        const std::vector<float> samples = valueOrThrow(onGlThread([&] { return s.renderSound(seconds); }));
        const py::ssize_t frames = static_cast<py::ssize_t>(samples.size() / 2);
        py::array_t<float> out({frames, py::ssize_t(2)});
        std::copy(samples.begin(), samples.begin() + frames * 2, out.mutable_data());
        return out;
    }

    // Session.record(): the frames rendered on the GL thread, encoded by toyhost's own encoders.
    std::vector<std::string> record(const std::vector<InputEvent>& events, const std::string& out, int frames,
                                    int every, const std::string& pass) {
        Session& s = open();
        Session::RecordRequest request{out, frames, every, pass, events};
        return valueOrThrow(onGlThread([&] { return s.record(request); }));
    }

    Reloaded reload(const Shadertoy& next) {
        Session& s = open();
        // Planned here (files, decoding, a preprocessor child) with the GIL released; the GL
        // thread only applies it.
        PreparedReload prepared = withoutGil([&] { return s.prepareReload(next); });
        Reloaded outcome = valueOrThrow(onGlThread([&] { return s.reload(std::move(prepared)); }));
        width_ = s.width();
        height_ = s.height();
        return outcome;
    }

    void restart() {
        Session& s = open();
        onGlThread([&] { s.restart(); });
    }
    void resize(int w, int h) {
        Session& s = open();
        throwIfFailed(onGlThread([&] { return s.resize(w, h); }));
        width_ = s.width();
        height_ = s.height();
    }

    // Cheap reads of the session's own state (no GL): answered on the worker all the same, so that
    // they never race a step running there.
    int nextFrame() { return ask([](Session& s) { return s.frame(); }); }
    int width() const { return width_; }
    int height() const { return height_; }
    std::vector<Diagnostic> notices() { return ask([](Session& s) { return s.notices(); }); }
    std::string backend() { return ask([](Session& s) { return s.backend(); }); }

private:
    // The session freed on its thread, then the thread ended.
    void stopAfter() {
        worker_.call([&] { session_.reset(); });
        worker_.stop();
    }
    Session& open() {
        if (!session_) throw ToyhostError(Error("the session is closed", Code::Usage));
        if (!worker_.inOwnProcess())
            throw ToyhostError(Error("the session was made in another process (before a fork): make one in this "
                                     "process (its GL thread does not exist here)",
                                     Code::Usage));
        return *session_;
    }
    template <class Question>
    auto ask(Question question) -> std::invoke_result_t<Question&, Session&> {
        Session& s = open();
        return onGlThread([&] { return question(s); });
    }
    // `job` on the worker, waited for with the GIL released.
    template <class Job>
    auto onGlThread(Job job) -> std::invoke_result_t<Job&> {
        return withoutGil([&] { return worker_.call(job); });
    }

    GlWorker worker_;
    std::unique_ptr<Session> session_;  // created, used and destroyed on worker_
    std::vector<std::weak_ptr<PythonFrameStream>> streams_;  // render() iterations, cancelled at close()
    int width_ = 0;  // the canvas, kept here so that allocating a frame's array needs no round trip
    int height_ = 0;
};

// The next frame of a render() as (iFrame, array), the array owning the frame's memory; None at the
// end.
template <class T>
py::object arrayOwning(int frame, int width, int height, std::unique_ptr<T[]> values) {
    T* data = values.get();
    py::capsule owner(values.release(), [](void* p) { delete[] static_cast<T*>(p); });
    return py::make_tuple(frame, py::array_t<T>({height, width, 4}, data, owner));
}

py::object nextRendered(PythonFrameStream& stream) {
    std::optional<RenderedFrame> frame;
    const bool mainThread = onMainThread();
    const std::function<bool()> interrupted = mainThread ? std::function<bool()>(signalRaised) : nullptr;
    try {
        // The stream's own pipe is the wakeup fd while the main thread waits for a frame, so that
        // the worker sees a signal before it starts another frame.
        std::optional<WakeupFdGuard> wakeup;
        if (mainThread) wakeup.emplace(stream.signalWakeupFd(), [&stream] { return stream.takeSignalBytes(); });
        // A signal that came before the pipe was there is seen now, not a frame later.
        if (interrupted && signalRaised()) throw PythonFrameStream::Interrupted{};
        frame = withoutGil([&] { return stream.next(interrupted); });
    } catch (const PythonFrameStream::Interrupted&) {
        throw py::error_already_set();  // the handler's exception (KeyboardInterrupt)
    }
    if (!frame) return py::none();
    if (frame->floats) return arrayOwning(frame->frame, frame->width, frame->height, std::move(frame->floats));
    return arrayOwning(frame->frame, frame->width, frame->height, std::move(frame->bytes));
}

// What Python's layer converts a setting's value to before it comes here (python/toyhost/_args.py),
// by the C++ type of its row: a trailing "?" means None is "not given".
template <class T> struct SettingKind;
template <> struct SettingKind<bool> { static constexpr const char* name = "flag"; };
template <> struct SettingKind<double> { static constexpr const char* name = "real"; };
template <> struct SettingKind<std::optional<int>> { static constexpr const char* name = "int?"; };
template <> struct SettingKind<std::optional<double>> { static constexpr const char* name = "real?"; };
template <> struct SettingKind<std::optional<std::string>> { static constexpr const char* name = "text?"; };
template <> struct SettingKind<std::optional<std::filesystem::path>> { static constexpr const char* name = "path?"; };
template <> struct SettingKind<std::vector<std::filesystem::path>> { static constexpr const char* name = "paths"; };
template <> struct SettingKind<std::vector<std::string>> { static constexpr const char* name = "macros"; };
template <> struct SettingKind<TOYHOST_SETTINGS_MEDIA_FILES> { static constexpr const char* name = "named_paths"; };

// The settings Python gives, by member name (its layer checked and converted each value and split
// size into width and height); a member left out is not given.
SessionSettings settingsFrom(const py::dict& given) {
    SessionSettings settings;
#define TOYHOST_SETTING_FROM_PYTHON(Type, member, key, initial, fallback) \
    if (given.contains(#member)) settings.member = given[#member].cast<Type>();
    TOYHOST_SESSION_SETTINGS(TOYHOST_SETTING_FROM_PYTHON)
#undef TOYHOST_SETTING_FROM_PYTHON
    return settings;
}

}  // namespace

void bindSession(py::module_& module) {
    // The settings' list (toyhost/Settings.h) as (member, key, kind, fallback, initial) rows, the
    // last two as the list spells them: Python's Session keywords, their checks, Session's
    // signature (python/toyhost/_settings.py writes it) and toyhost.defaults()' link are made from it.
    module.def("setting_fields", [] {
        py::list rows;
#define TOYHOST_SETTING_ROW(Type, member, key, initial, fallback) \
    rows.append(py::make_tuple(#member, key, SettingKind<Type>::name, #fallback, #initial));
        TOYHOST_SESSION_SETTINGS(TOYHOST_SETTING_ROW)
#undef TOYHOST_SETTING_ROW
        return rows;
    });
    py::class_<Reloaded>(module, "Reloaded", "What a reload did (Session.reload).")
        .def_readonly("applied", &Reloaded::applied)
        .def_readonly("structure_changed", &Reloaded::structureChanged)
        .def_readonly("recompiled", &Reloaded::recompiled)
        .def_readonly("problems", &Reloaded::problems)
        .def("__repr__", [](const Reloaded& r) {
            return "<toyhost.Reloaded applied=" + std::string(r.applied ? "True" : "False") +
                   " structure_changed=" + (r.structureChanged ? "True" : "False") + " recompiled=" +
                   std::to_string(r.recompiled.size()) + " problems=" + std::to_string(r.problems.size()) + ">";
        });
    py::class_<PythonFrameStream, std::shared_ptr<PythonFrameStream>>(module, "FrameStream",
                                                            "Session.render()'s frames, rendered ahead.")
        .def("next", &nextRendered, "The next (iframe, array), or None after the last.")
        .def("cancel", [](PythonFrameStream& stream) { stream.cancel(); },
             "Stops rendering; frames not taken are dropped.");
    py::class_<NativeSession>(module, "NativeSession")
        .def(py::init([](const Shadertoy& shadertoy, const py::dict& settings) {
                 return std::make_unique<NativeSession>(shadertoy, settingsFrom(settings));
             }),
             py::arg("shadertoy"), py::arg("settings"))
        .def("close", &NativeSession::close)
        .def_property_readonly("closed", &NativeSession::closed)
        .def("step", &NativeSession::step, py::arg("events"), py::arg("time"), py::arg("time_delta"),
             py::arg("frame_rate"))
        .def("seek", &NativeSession::seek, py::arg("frame"))
        .def("render", &NativeSession::render, py::arg("events"), py::arg("frames"), py::arg("every"),
             py::arg("pass_"), py::arg("floats"), py::keep_alive<0, 1>())
        .def("read_uint8", &NativeSession::read<std::uint8_t>, py::arg("pass_"))
        .def("read_float32", &NativeSession::read<float>, py::arg("pass_"))
        .def("read_into_uint8", &NativeSession::readInto<std::uint8_t>, py::arg("pass_"), py::arg("out"))
        .def("read_into_float32", &NativeSession::readInto<float>, py::arg("pass_"), py::arg("out"))
        .def("render_sound", &NativeSession::renderSound, py::arg("seconds"))
        .def("set_channel", &NativeSession::setChannel, py::arg("pass_"), py::arg("channel"), py::arg("array"),
             py::arg("filter"), py::arg("wrap"))
        .def("record", &NativeSession::record, py::arg("events"), py::arg("out"), py::arg("frames"), py::arg("every"),
             py::arg("pass_"))
        .def("reload", &NativeSession::reload, py::arg("shadertoy"))
        .def("restart", &NativeSession::restart)
        .def("resize", &NativeSession::resize, py::arg("width"), py::arg("height"))
        .def_property_readonly("next_frame", &NativeSession::nextFrame)
        .def_property_readonly("width", &NativeSession::width)
        .def_property_readonly("height", &NativeSession::height)
        .def_property_readonly("notices", &NativeSession::notices)
        .def_property_readonly("backend", &NativeSession::backend);
}

}  // namespace toyhost::python
