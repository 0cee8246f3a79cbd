// MouseState: the button/pointer state behind Shadertoy's iMouse uniform, fed by window events or
// by a MouseScriptPlayer. Pure logic, no GL context needed.
// Coordinates are canvas pixels with the origin at the bottom-left, as iMouse holds them.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace toyhost {

// Reproduces the site's player (the page's render loop builds iMouse from mMousePos*/mMouseOri*,
// negating ori.x while the button is up and ori.y on every frame but the click's):
//   xy  the pointer position, updated only while the button is held (it keeps the last dragged
//       position after release); (0,0) before any click.
//   z   +click.x while held, -click.x after release.
//   w   +click.y on the frame of the click only, -click.y on every later frame.
// Before any click all four are 0. A press and a release within one frame still show the click
// signal on that frame (w > 0) but z is already negative.
// The site delivers whole pixels (Math.floor of the canvas position); a window backend should
// floor too, scripted positions are used as given.
// Checked by tests/unit/test_input_mouse.cpp.
class MouseState {
public:
    // Button goes down at (x, y): xy and the click origin both become (x, y). A second press
    // without a release starts a new click.
    void press(float x, float y);
    // Pointer moves; ignored unless the button is held.
    void move(float x, float y);
    // Button goes up; xy keeps the last position.
    void release();

    // The iMouse value for the frame about to be rendered.
    glm::vec4 uniform() const;
    // Call after each rendered frame: the click signal (w > 0) lasts one frame.
    void endFrame();

    bool held() const { return held_; }

    // The whole state, for checkpoints (a resumed run continues exactly where it stopped).
    struct Saved {
        glm::vec2 position{0.0f};
        glm::vec2 clickOrigin{0.0f};
        bool held = false;
        bool clickedThisFrame = false;
        bool everClicked = false;
    };
    Saved save() const { return {position_, clickOrigin_, held_, clickedThisFrame_, everClicked_}; }
    void restore(const Saved& s) {
        position_ = s.position;
        clickOrigin_ = s.clickOrigin;
        held_ = s.held;
        clickedThisFrame_ = s.clickedThisFrame;
        everClicked_ = s.everClicked;
    }

private:
    glm::vec2 position_{0.0f};
    glm::vec2 clickOrigin_{0.0f};
    bool held_ = false;
    bool clickedThisFrame_ = false;
    bool everClicked_ = false;
};

}  // namespace toyhost
