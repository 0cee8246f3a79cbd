void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 self = fetch(iChannel0, fragCoord);   // previous frame (0 at frame 0)
    vec4 later = fetch(iChannel1, fragCoord);  // Buffer B runs later: previous frame
    fragColor = vec4(self.x + 1.0, float(iFrame), later.x, 0.25);
}
