// A mouse-driven viewer that shows nothing once the mouse has been used (iMouse.x is no longer 0):
// the probe's drag makes it one colour, while the site without input shows the gradient. The key
// script's first frame, with no input at all, finds that.
void mainImage(out vec4 c, in vec2 f) {
    c = iMouse.x > 0.0 ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(vec3(f.x / iResolution.x), 1.0);
}
