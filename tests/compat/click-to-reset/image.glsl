// A "click to reset" shader: black while the button is held, a gradient otherwise. A runner that
// holds the mouse to the last frame judges it black.
void mainImage(out vec4 c, in vec2 f) {
    c = iMouse.z > 0.0 ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(f / iResolution.xy, 0.5, 1.0);
}
