// compareShadertoys and compareImages for Python: settings from keyword arguments, the run on a
// big-stack GL thread (runOnGlThread) while the GIL is released, difference images as numpy arrays.
#include "CompareBinding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <cstdint>
#include <poll.h>
#include <thread>
#include <unistd.h>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <toyhost/Compare.h>
#include <toyhost/Session.h>

#include "Errors.h"
#include "Gil.h"
#include "SessionBinding.h"
#include "Signals.h"

namespace py = pybind11;

namespace toyhost::python {

namespace {

// A (height, width, 4) uint8 C-contiguous array's bytes, or a usage error naming `what`.
std::span<const std::uint8_t> frameBytes(const py::array& array, const char* what) {
    const bool fits = array.ndim() == 3 && array.shape(2) == 4 && array.dtype().is(py::dtype::of<std::uint8_t>()) &&
                      (array.flags() & py::array::c_style);
    if (!fits)
        throw ToyhostError(Error(std::string(what) + ": expected a C-contiguous uint8 array of shape (height, width, 4)",
                                 Code::Usage));
    return {static_cast<const std::uint8_t*>(array.data()), static_cast<std::size_t>(array.size())};
}

py::object imageOrNone(const std::vector<std::uint8_t>& rgba, int width, int height) {
    if (rgba.empty()) return py::none();
    py::array_t<std::uint8_t> out({py::ssize_t(height), py::ssize_t(width), py::ssize_t(4)});
    std::copy(rgba.begin(), rgba.end(), out.mutable_data());
    return out;
}

// Runs the comparison on a GL thread. On Python's main thread the wait is woken by a signal
// (Ctrl-C): its handler runs at once, and when it raises (KeyboardInterrupt) the comparison stops
// after the frame being compared and the exception propagates; a handler that raises nothing lets
// it go on. Elsewhere the wait is plain.
Result<CompareReport> runComparison(const Shadertoy& a, const Shadertoy& b, CompareSettings settings) {
    std::atomic<bool> cancel{false};
    const std::function<bool(const ComparedFrame&)> onFrame = std::move(settings.onFrame);
    settings.onFrame = [&cancel, onFrame](const ComparedFrame& compared) {
        if (cancel.load()) return false;
        return onFrame ? onFrame(compared) : true;
    };
    auto compare = [&] {
        Result<CompareReport> result = Error("compare: not run", Code::Internal);
        runOnGlThread([&] { result = compareShadertoys(a, b, settings); });
        return result;
    };
    if (!onMainThread()) return withoutGil(compare);

    SignalPipe signals;
    SignalPipe done;  // written once the comparison has returned
    WakeupFdGuard wakeup(signals.writeFd(), [&signals] { return signals.take(); });
    if (signalRaised()) throw py::error_already_set();  // a signal before the pipe was there
    Result<CompareReport> result = Error("compare: not run", Code::Internal);
    std::thread worker([&] {
        try {
            result = compare();
        } catch (const std::exception& e) {  // escaping a thread would end the process
            result = Error(std::string("compare: ") + e.what(), Code::Internal);
        }
        const char byte = 1;
        const ssize_t written = ::write(done.writeFd(), &byte, 1);
        (void)written;  // a pipe of its own, empty: one byte always fits
    });
    bool raised = false;
    while (true) {
        pollfd fds[2] = {{done.readFd(), POLLIN, 0}, {signals.readFd(), POLLIN, 0}};
        withoutGil([&] { ::poll(fds, 2, -1); });
        if (fds[0].revents) break;
        if ((fds[1].revents & POLLIN) && signals.drain() && !raised && PyErr_CheckSignals() != 0) {
            raised = true;  // the handler's exception is set; the comparison stops at its next frame
            cancel.store(true);
        }
    }
    withoutGil([&] { worker.join(); });
    if (raised) throw py::error_already_set();
    return result;
}

py::dict differenceAsDict(const FrameDifference& d, int width, int height) {
    py::dict out;
    out["frame"] = d.frame;
    out["time"] = d.time;
    out["psnr"] = d.psnr;
    out["max_diff"] = d.maxDiff;
    out["mean_diff"] = d.meanDiff;
    out["differing_pixels"] = d.differingPixels;
    out["first_x"] = d.firstX < 0 ? py::none() : py::cast(d.firstX);
    out["first_y"] = d.firstY < 0 ? py::none() : py::cast(d.firstY);
    out["within_tolerance"] = d.withinTolerance;
    out["diff_image"] = imageOrNone(d.diffImage, width, height);
    return out;
}

CompareTolerance toleranceFrom(std::optional<double> minPsnr, std::optional<int> maxDiff) {
    CompareTolerance tolerance;
    tolerance.minPsnr = minPsnr;
    tolerance.maxDiff = maxDiff;
    return tolerance;
}

}  // namespace

void bindCompare(py::module_& m) {
    m.def(
        "compare",
        [](const Shadertoy& a, const Shadertoy& b, std::optional<int> width, std::optional<int> height,
           std::optional<double> fps, double startTime, const std::optional<std::string>& date,
           const std::vector<std::filesystem::path>& mediaFolders,
           const std::vector<std::pair<std::string, std::filesystem::path>>& mediaFiles,
           std::optional<double> frameTimeout, std::optional<double> compileTimeout, int frames,
           const std::string& pass, std::optional<double> minPsnr, std::optional<int> maxDiff,
           std::optional<std::pair<float, float>> mouse, const std::optional<std::filesystem::path>& mouseScript,
           const std::optional<std::filesystem::path>& keyScript, bool keepDiffImages,
           int diffGain, bool stopAtFirstDifference) {
            refuseAfterForkWithGlOpen();
            CompareSettings settings;
            settings.session.width = width;
            settings.session.height = height;
            settings.session.fps = fps;
            settings.session.startTime = startTime;
            settings.session.date = date;
            settings.session.mediaFolders = mediaFolders;
            settings.session.mediaFiles = mediaFiles;
            settings.session.frameTimeout = frameTimeout;
            settings.session.compileTimeout = compileTimeout;
            settings.frames = frames;
            settings.pass = pass;
            settings.tolerance = toleranceFrom(minPsnr, maxDiff);
            settings.session.mouseScript = mouseScript;
            settings.session.keyScript = keyScript;
            settings.keepDiffImages = keepDiffImages;
            settings.diffGain = diffGain;
            if (mouse)  // the button pressed at (x, y) before frame 0 and held, as the CLI's --mouse
                settings.input = [at = *mouse](int frame, double) {
                    return frame == 0 ? std::vector<InputEvent>{InputEvent::mouseDown(at.first, at.second)}
                                      : std::vector<InputEvent>{};
                };
            if (stopAtFirstDifference)
                settings.onFrame = [](const ComparedFrame& compared) { return compared.difference.withinTolerance; };
            CompareReport report = valueOrThrow(runComparison(a, b, std::move(settings)));
            py::dict out;
            out["width"] = report.width;
            out["height"] = report.height;
            out["fps"] = report.fps;
            out["start_time"] = report.startTime;
            out["pass_"] = report.pass;
            py::list list;
            for (const FrameDifference& d : report.frames) list.append(differenceAsDict(d, report.width, report.height));
            out["frames"] = list;
            out["first_differing_frame"] =
                report.firstDifferingFrame ? py::cast(*report.firstDifferingFrame) : py::object(py::none());
            out["min_psnr"] = report.minPsnr;
            out["max_diff"] = report.maxDiff;
            return out;
        },
        py::arg("a"), py::arg("b"), py::arg("width"), py::arg("height"), py::arg("fps"), py::arg("start_time"),
        py::arg("date"), py::arg("media_folders"), py::arg("media_files"), py::arg("frame_timeout"),
        py::arg("compile_timeout"), py::arg("frames"), py::arg("pass_"), py::arg("min_psnr"), py::arg("max_diff"),
        py::arg("mouse"), py::arg("mouse_script"), py::arg("key_script"), py::arg("keep_diff_images"),
        py::arg("diff_gain"), py::arg("stop_at_first_difference"));

    m.def(
        "compare_images",
        [](const py::array& a, const py::array& b, int channels, std::optional<double> minPsnr,
           std::optional<int> maxDiff, bool diffImage, int diffGain) {
            const std::span<const std::uint8_t> first = frameBytes(a, "a");
            const std::span<const std::uint8_t> second = frameBytes(b, "b");
            if (a.shape(0) != b.shape(0) || a.shape(1) != b.shape(1))
                throw ToyhostError(Error("compare_images: a and b have different shapes", Code::Usage));
            const int height = static_cast<int>(a.shape(0)), width = static_cast<int>(a.shape(1));
            std::vector<std::uint8_t> diff;
            FrameDifference d = valueOrThrow(withoutGil([&] {
                return compareImages(first, second, width, height, channels, toleranceFrom(minPsnr, maxDiff),
                                     diffImage ? &diff : nullptr, diffGain);
            }));
            d.diffImage = std::move(diff);
            return differenceAsDict(d, width, height);
        },
        py::arg("a"), py::arg("b"), py::arg("channels"), py::arg("min_psnr"), py::arg("max_diff"),
        py::arg("diff_image"), py::arg("diff_gain"));
}

}  // namespace toyhost::python
