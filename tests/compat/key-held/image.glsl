// Draws only while the space bar is held (the keyboard texture's row 0 at keyCode 32): one colour
// with the mouse alone; the runner's key script finds it.
void mainImage(out vec4 c, in vec2 f) {
    float held = texelFetch(iChannel0, ivec2(32, 0), 0).x;
    c = vec4(vec3(held * f.x / iResolution.x), 1.0);
}
