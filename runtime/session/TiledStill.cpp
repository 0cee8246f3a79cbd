#include "session/TiledStill.h"

#include <algorithm>
#include <cstring>
#include <system_error>

#include "capture/FrameStream.h"
#include "image/BandedImageWriter.h"

namespace toyhost {

namespace fs = std::filesystem;

TiledStill::TiledStill(const SessionPlan& plan)
    : plan_(plan), width_(*plan.options.settings.width), height_(*plan.options.settings.height),
      floats_(plan.output && plan.output->kind().floats), thread_([this] { loop(); }) {}

TiledStill::~TiledStill() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        jobs_.clear();  // a file not finished goes with its writer (its temporary file removed)
        changed_.notify_all();
    }
    thread_.join();
}

void TiledStill::loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // stopping, nothing left
        Job job = std::move(jobs_.front());
        jobs_.pop_front();
        busy_ = true;
        const bool skip = failed_.has_value();  // after a failure the rest of that file is dropped
        lock.unlock();
        Status done = skip ? okStatus() : job();
        job = nullptr;  // its file and band go here, off the lock
        lock.lock();
        busy_ = false;
        if (!done && !failed_) failed_ = done.error();
        changed_.notify_all();
    }
}

void TiledStill::submit(Job job) {
    std::unique_lock<std::mutex> lock(mutex_);
    // One band is written while the next one is drawn: two bands of rows in memory at most.
    changed_.wait(lock, [&] { return jobs_.empty() && !busy_; });
    jobs_.push_back(std::move(job));
    changed_.notify_all();
}

Status TiledStill::drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() && !busy_; });
    if (failed_) return *failed_;
    return okStatus();
}

Status TiledStill::render(Player& player, int frame) {
    const SessionOptions& o = plan_.options;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (failed_) return *failed_;
    }
    const bool captured = plan_.output && FrameStream::captured(frame, *o.frames, *o.captureEvery);
    if (plan_.output && !captured) return okStatus();  // Image is drawn only on captured frames
    const int tileWidth = player.width(), tileHeight = player.height();
    auto file = std::make_shared<std::unique_ptr<BandedImageWriter>>();
    fs::path path;
    if (captured) {
        path = plan_.output->pathFor(frame);
        const auto format = floats_ ? BandedImageWriter::Format::Exr : BandedImageWriter::Format::Png;
        submit([file, path, format, this, level = *o.pngLevel, exr = o.exr]() -> Status {
            Result<std::unique_ptr<BandedImageWriter>> opened =
                BandedImageWriter::open(path, width_, height_, format, level, exr);
            if (!opened) return opened.error();
            *file = std::move(*opened);
            return okStatus();
        });
    }
    const std::size_t rowValues = static_cast<std::size_t>(width_) * 4;
    // Tiles sit on a grid from the canvas's bottom-left corner (the top row and right column of
    // tiles reach beyond it), so that every tile's origin is even when the tile is (fitPlayer):
    // derivatives pair the same 2x2 quads of pixels as in an untiled render. Bands go top first.
    for (int row = (height_ - 1) / tileHeight; row >= 0; --row) {
        // A band that could not be written (a full disk, `ulimit -f`) ends the frame before the next
        // band is drawn (once a defect: a 65536x65536 EXR drew every tile for minutes after the first
        // write failed). The file's writer goes with its jobs: its temporary file is removed.
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (failed_) return *failed_;
        }
        const int originY = row * tileHeight;
        const int bottom = originY, top = std::min(height_, originY + tileHeight), rows = top - bottom;
        std::shared_ptr<Band> band;
        if (captured) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!spare_.empty()) {
                band = std::move(spare_.front());
                spare_.pop_front();
            }
        }
        if (captured && !band) band = std::make_shared<Band>();
        if (band) (floats_ ? band->floats.resize(rows * rowValues) : band->bytes.resize(rows * rowValues));
        for (int left = 0; left < width_; left += tileWidth) {
            player.drawImageAt({left, originY});
            if (!captured) continue;
            const std::size_t columns = static_cast<std::size_t>(std::min(tileWidth, width_ - left)) * 4;
            if (floats_) player.readRgba32f(PassId::Image, tileFloats_);
            else player.readRgba8(PassId::Image, tileBytes_);
            for (int y = bottom; y < top; ++y) {
                const std::size_t from = static_cast<std::size_t>(y - originY) * tileWidth * 4;  // bottom first
                const std::size_t to = static_cast<std::size_t>(top - 1 - y) * rowValues + static_cast<std::size_t>(left) * 4;
                if (floats_) std::memcpy(band->floats.data() + to, tileFloats_.data() + from, columns * sizeof(float));
                else std::memcpy(band->bytes.data() + to, tileBytes_.data() + from, columns);
            }
        }
        if (!captured) continue;
        submit([this, file, band, rows]() -> Status {
            Status written = floats_ ? (*file)->writeRows(std::span<const float>(band->floats), rows)
                                     : (*file)->writeRows(std::span<const std::uint8_t>(band->bytes), rows);
            std::lock_guard<std::mutex> lock(mutex_);
            spare_.push_back(band);
            return written;
        });
    }
    if (captured)
        submit([this, file, path]() -> Status {
            if (Status finished = (*file)->finish(); !finished) return finished;
            std::error_code ec;
            const std::uintmax_t size = fs::file_size(path, ec);
            std::lock_guard<std::mutex> lock(mutex_);
            written_.push_back(path);
            if (!ec) bytes_ += size;
            return okStatus();
        });
    return okStatus();
}

Status TiledStill::complete() { return drain(); }

void TiledStill::report(SessionReport& report) const {
    report.files.insert(report.files.end(), written_.begin(), written_.end());
    report.bytesWritten += bytes_;
}

std::string TiledStill::abandon() {
    {
        std::unique_lock<std::mutex> lock(mutex_);
        jobs_.clear();  // the unfinished file's writer goes with its jobs (temporary file removed)
        changed_.wait(lock, [&] { return !busy_; });
    }
    const std::size_t n = written_.size();
    return "; " + std::to_string(n) + (n == 1 ? " file" : " files") + " written";
}

}  // namespace toyhost
