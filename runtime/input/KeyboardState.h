// KeyboardState: the bytes of Shadertoy's 256x3 keyboard texture (ctype "keyboard"), fed by window
// key events or by a KeyScriptPlayer. Pure logic, no GL context needed; the renderer uploads
// texels() as a single-channel 8-bit texture when revision() changed.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

namespace toyhost {

// Indexed by JavaScript keyCode (see KeyCodes.h). Reproduces the site's Effect.SetKeyDown /
// SetKeyUp / end of Effect.Paint (effect.js):
//   row 0 (y=0)  255 while the key is held, else 0;
//   row 1        255 from the press until the end of the frame (endFrame) or the release,
//                whichever comes first: the site's key-up clears row 1 as well, so a press and a
//                release within one frame leave row 1 at 0;
//   row 2        toggle: flips between 0 and 255 on every press.
// A press of a key that is already held (browser auto-repeat) changes nothing: the site's
// SetKeyDown returns early when row 0 is already 255.
// Key codes outside 0..255 are ignored (the site would write past row 0; we never do).
// Checked by tests/unit/test_input_keyboard.cpp.
class KeyboardState {
public:
    static constexpr int kWidth = 256;
    static constexpr int kHeight = 3;
    enum Row : int { kHeldRow = 0, kWentDownRow = 1, kToggleRow = 2 };

    void press(int keyCode);
    void release(int keyCode);
    // Call after each rendered frame: clears row 1.
    void endFrame();

    // 256*3 bytes, row 0 first: row 0 is y=0, the bottom row of the texture, which is the row
    // glTexImage2D reads first. Upload with GL_R8 / GL_RED / GL_UNSIGNED_BYTE and unpack
    // alignment 1.
    std::span<const std::uint8_t> texels() const { return texels_; }
    std::uint8_t texel(int keyCode, Row row) const;

    // Increases whenever texels() changes and only then. A renderer remembers the revision it
    // uploaded last and uploads again only when this differs, so an idle keyboard costs nothing
    // per frame; several consumers can each keep their own copy of the number.
    std::uint64_t revision() const { return revision_; }

    // Sets every texel (a resumed checkpoint); counts as a change.
    void restore(std::span<const std::uint8_t, kWidth * kHeight> texels) {
        std::copy(texels.begin(), texels.end(), texels_.begin());
        ++revision_;
    }

private:
    std::uint8_t& at(int keyCode, Row row) { return texels_[row * kWidth + keyCode]; }

    std::array<std::uint8_t, kWidth * kHeight> texels_{};
    std::uint64_t revision_ = 0;
};

}  // namespace toyhost
