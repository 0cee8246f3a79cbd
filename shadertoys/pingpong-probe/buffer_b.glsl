void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 a = fetch(iChannel0, fragCoord);      // Buffer A ran earlier: this frame
    vec4 self = fetch(iChannel1, fragCoord);   // previous frame
    fragColor = vec4(10.0 * a.x, self.y + a.x, a.y, 0.5);
}
