// timeline-probe Buffer A: a trail of the mouse and the 'A' key, accumulated frame by frame, so
// that a frame shows the whole input history a run stepped through (its timeline), not only the
// latest state.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 previous = texelFetch(iChannel0, ivec2(fragCoord), 0) * 0.9;
    float pressed = iMouse.z > 0.0 ? 1.0 : 0.0;
    float near = 1.0 - smoothstep(2.0, 6.0, length(fragCoord - iMouse.xy));
    float key = texelFetch(iChannel1, ivec2(65, 0), 0).x;
    float row = step(abs(fragCoord.y - float(iFrame % int(iResolution.y))), 0.5);
    fragColor = max(previous, vec4(near * pressed, near, key * row, 1.0));
}
