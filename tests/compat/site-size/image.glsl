// Draws only right of pixel 500, for the site's 800x450 canvas: nothing of it falls on 160x90 or
// 320x180, so only the third size shows it.
void mainImage(out vec4 c, in vec2 f) {
    c = vec4(vec3(step(500.0, f.x) * fract(f.y / 16.0)), 1.0);
}
