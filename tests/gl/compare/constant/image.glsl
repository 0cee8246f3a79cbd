// base with one constant changed: the blue band starts at x = 0.75 instead of 0.5.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float edge = 0.75;
    fragColor = vec4(uv.x, uv.y, uv.x > edge ? 1.0 : 0.0, 1.0);
    fragColor.g *= 0.5 + 0.5 * cos(iTime);
}
