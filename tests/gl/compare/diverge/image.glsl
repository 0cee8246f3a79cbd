// base until iTime 0.25, then red inverted in the bottom half (fps 10: frame 3 and later).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float edge = 0.5;
    fragColor = vec4(uv.x, uv.y, uv.x > edge ? 1.0 : 0.0, 1.0);
    fragColor.g *= 0.5 + 0.5 * cos(iTime);
    if (iTime >= 0.25 && fragCoord.y < iResolution.y * 0.5) fragColor.r = 1.0 - fragColor.r;
}
