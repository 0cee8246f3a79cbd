// A green-screen key over a stock video: green pixels show a backdrop, the rest the video. The
// stand-in video has no green, so toyhost shows the stand-in itself; the pass rests on the
// stand-in's content (black without it), not on anything the site would show.
void mainImage(out vec4 c, in vec2 f) {
    vec3 v = texture(iChannel0, f / iResolution.xy).rgb;
    bool green = v.g > 0.6 && v.r < 0.4 && v.b < 0.4;
    c = vec4(green ? vec3(0.0) : v, 1.0);
}
