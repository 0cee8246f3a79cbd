// timeline-probe Image: every input of a headless frame at once: Buffer A's trail of the mouse and
// keys on the left, iTime, iDate, iFrame, iTimeDelta and the toggle row of 'A' on the right. For
// tests that render one scripted run through every surface (CLI, C++ Session, Python, compare).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    if (uv.x < 0.5) {
        fragColor = vec4(texelFetch(iChannel0, ivec2(fragCoord), 0).rgb, 1.0);
        return;
    }
    float toggled = texelFetch(iChannel1, ivec2(65, 2), 0).x;
    fragColor = vec4(fract(iTime * 0.37 + uv.y), fract(iDate.w * 0.05 + uv.x),
                     fract(float(iFrame) / 7.0 + iTimeDelta * 3.0) * 0.8 + toggled * 0.2, 1.0);
}
