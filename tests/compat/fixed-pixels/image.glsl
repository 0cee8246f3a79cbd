// Draws at fixed pixel positions (a ring of radius 100 px around (300, 160), for an 800x450
// layout): nothing of it falls on a 160x90 canvas, so the small size alone calls it empty.
void mainImage(out vec4 c, in vec2 f) {
    float ring = step(abs(length(f - vec2(300.0, 160.0)) - 100.0), 3.0);
    c = vec4(vec3(ring), 1.0);
}
