// lake-optics — Buffer A: the selected water preset as a one-pixel state.
//
// Layout: texel (0,0).x = preset index 0, 1 or 2 (keys 1, 2, 3), .y = iTime of the last preset
// key (for the Image's 2 s indicator), .w = 1 once a key was pressed; every other texel is 0.
// The pass reads its own previous frame (iChannel0 = Buffer A) so the choice persists after
// the key is released. Buffers start cleared to 0, so the default is index 0 (tropical ocean).
// iChannel1 = keyboard: row 0 = key held, row 1 = key went down this frame (both accepted, so
// a press that is shorter than a frame is not missed).

float keyDown(int code) {
    return max(texelFetch(iChannel1, ivec2(code, 0), 0).x,
               texelFetch(iChannel1, ivec2(code, 1), 0).x);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    if (ivec2(fragCoord) != ivec2(0)) {
        fragColor = vec4(0.0);
        return;
    }
    vec4 state = texelFetch(iChannel0, ivec2(0), 0);
    float preset = clamp(floor(state.x + 0.5), 0.0, 2.0);   // guard against anything odd in the state
    float pressed = -1.0;
    if (keyDown(49) > 0.5) pressed = 0.0;           // '1' tropical ocean
    if (keyDown(50) > 0.5) pressed = 1.0;           // '2' muddy river
    if (keyDown(51) > 0.5) pressed = 2.0;           // '3' tannin (peat) lake
    if (pressed >= 0.0) state = vec4(pressed, iTime, 0.0, 1.0);
    else state = vec4(preset, state.y, 0.0, state.w);
    fragColor = state;
}
