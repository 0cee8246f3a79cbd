// One colour that never changes: degenerate output, which the compatibility runner must fail.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(0.2, 0.4, 0.6, 1.0);
}
