#include "media/LiveAudio.h"

#include <chrono>
#include <cstring>

namespace toyhost {

namespace {
constexpr std::size_t kRingSamples = std::size_t(1) << 16;  // about 1.5 s at 44100 Hz
}  // namespace

bool LiveAudio::isLiveSource(const std::string& spec) {
    return spec.rfind("alsa:", 0) == 0 || spec.rfind("pulse:", 0) == 0 || spec.rfind("lavfi:", 0) == 0;
}

LiveAudio::LiveAudio(ChildProcess child, std::unique_ptr<TemporaryFiles> log, std::string spec)
    : child_(std::move(child)), log_(std::move(log)), spec_(std::move(spec)), ring_(kRingSamples, 0.0f) {}

Result<std::unique_ptr<LiveAudio>> LiveAudio::open(const std::string& spec, int sampleRate) {
    if (!isLiveSource(spec))
        return Error(spec + ": not a live audio source (alsa:DEVICE, pulse:DEVICE or lavfi:GRAPH)", Code::AudioLive);
    if (!findExecutable("ffmpeg"))
        return Error(spec + ": a live audio input needs ffmpeg, which was not found in PATH", Code::AudioFfmpegMissing);
    const std::size_t colon = spec.find(':');
    const std::string format = spec.substr(0, colon), device = spec.substr(colon + 1);
    std::vector<std::string> args = {"ffmpeg", "-nostdin", "-hide_banner", "-v", "error"};
    if (format == "lavfi") args.push_back("-re");  // a synthetic source at the pace of a real one
    args.insert(args.end(), {"-f", format, "-i", device, "-map", "0:a:0", "-f", "f32le", "-ac", "1", "-ar",
                             std::to_string(sampleRate), "pipe:1"});
    auto log = std::make_unique<TemporaryFiles>("live-audio", std::initializer_list<const char*>{"log"});
    if (!log->registerAll()) return Error(spec + ": not started: toyhost is stopping", Code::Interrupted);
    Result<ChildProcess> child = ChildProcess::spawnReading(args, (*log)[0]);
    if (!child) return Error(spec + ": " + child.error().first().message, Code::AudioLive);
    std::unique_ptr<LiveAudio> live(new LiveAudio(std::move(*child), std::move(log), spec));
    live->reader_ = std::thread([raw = live.get()] { raw->readLoop(); });
    std::unique_lock lock(live->mutex_);
    live->arrived_.wait_for(lock, std::chrono::seconds(5), [&] { return live->written_ > 0 || live->ended_; });
    if (live->written_ == 0) {
        const bool ended = live->ended_;
        lock.unlock();
        const std::string said = logTail((*live->log_)[0]);
        return Error(spec + ": " + (ended ? "ffmpeg could not open it" : "no samples came in 5 s") +
                         (said.empty() ? std::string() : "; ffmpeg said: " + said),
                     Code::AudioLive);
    }
    return live;
}

LiveAudio::~LiveAudio() {
    child_.killFromAnyThread();  // the reader's read() then ends
    if (reader_.joinable()) reader_.join();
    child_.kill();  // reaps
}

void LiveAudio::readLoop() {
    std::vector<std::byte> bytes(16384);
    std::size_t pending = 0;  // bytes of a sample split across two reads
    while (true) {
        Result<std::size_t> got = child_.read(std::span(bytes).subspan(pending));
        if (!got || *got == 0) break;
        const std::size_t total = pending + *got;
        const std::size_t samples = total / sizeof(float);
        {
            std::lock_guard lock(mutex_);
            for (std::size_t i = 0; i < samples; ++i) {
                float value = 0;
                std::memcpy(&value, bytes.data() + i * sizeof(float), sizeof(float));
                ring_[written_++ & (ring_.size() - 1)] = value;
            }
        }
        arrived_.notify_all();
        pending = total - samples * sizeof(float);
        std::memmove(bytes.data(), bytes.data() + samples * sizeof(float), pending);
    }
    std::lock_guard lock(mutex_);
    ended_ = true;
    arrived_.notify_all();
}

std::uint64_t LiveAudio::latest(std::span<float> out) const {
    std::lock_guard lock(mutex_);
    const std::size_t n = out.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t back = n - i;  // 1 = the newest
        out[i] = back <= written_ && back <= ring_.size() ? ring_[(written_ - back) & (ring_.size() - 1)] : 0.0f;
    }
    return written_;
}

}  // namespace toyhost
