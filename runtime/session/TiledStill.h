// TiledStill: a run whose canvas is larger than one framebuffer may be (a still of 20000x11250
// for print; llvmpipe's limit is 16384) or asked to be tiled (--tile). The Player's targets are
// one tile and iResolution is the whole canvas; each frame's Image is drawn tile by tile with
// fragCoord moved to the tile's place (Player::drawImageAt), read back, and the captured frames are
// written band by band, top first, by a thread of their own (image/BandedImageWriter.h): at most
// two bands of rows are in memory, never the whole image. Only shadertoys without buffers can be
// tiled (their buffers would be canvas-sized); prepareSession refuses the others. Needs the
// player's GL context current on the calling thread.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/Result.h"
#include "player/Player.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {

class TiledStill {
public:
    // `plan.tile` is set; `plan.output`, when there is one, is a PNG or EXR file pattern.
    explicit TiledStill(const SessionPlan& plan);
    ~TiledStill();  // stops the writer; a file not finished is removed
    TiledStill(const TiledStill&) = delete;
    TiledStill& operator=(const TiledStill&) = delete;

    // A player for `plan`'s canvas (in `desc`) gets one tile as its targets and the canvas as
    // iResolution. A tile side is even (an odd one is rounded down): GPUs shade in 2x2 quads from
    // the target's corner, and dFdx/dFdy pair the canvas's quads only when every tile's origin is
    // even (issue 44). A canvas side within the tile is one tile, from 0.
    static int tileSide(int canvasSide, int tile) {
        const int even = tile - tile % 2;
        return canvasSide <= even ? canvasSide : even;
    }
    static void fitPlayer(PlayerDesc& desc, const SessionPlan& plan) {
        desc.canvasWidth = desc.width;
        desc.canvasHeight = desc.height;
        desc.width = tileSide(desc.width, plan.tile);
        desc.height = tileSide(desc.height, plan.tile);
    }

    // After `player` stepped frame `frame` (without drawing Image): draws its Image tile by tile
    // and, when the frame is captured, writes its file. An error of an earlier file's writing
    // comes back here.
    Status render(Player& player, int frame);
    // Waits for the files being written.
    Status complete();
    // The files written (complete) and their bytes.
    void report(SessionReport& report) const;
    // An interrupted run: the file being written is removed; "; 2 files written".
    std::string abandon();

private:
    struct Band {
        std::vector<std::uint8_t> bytes;  // rows top first (PNG)
        std::vector<float> floats;        // rows top first (EXR)
    };
    using Job = std::function<Status()>;
    void submit(Job job);  // waits until the writer is idle
    void loop();
    Status drain();

    const SessionPlan& plan_;
    int width_ = 0, height_ = 0;  // the canvas
    bool floats_ = false;         // EXR: the Image target is float
    std::vector<std::uint8_t> tileBytes_;
    std::vector<float> tileFloats_;
    std::deque<std::shared_ptr<Band>> spare_;  // band buffers to reuse (two in all)
    std::vector<std::filesystem::path> written_;
    std::uint64_t bytes_ = 0;
    // The writer thread and its queue.
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Job> jobs_;
    bool busy_ = false, stopping_ = false;
    std::optional<Error> failed_;
    std::thread thread_;
};

}  // namespace toyhost
