// lake-optics — Buffer A: the selected water preset as a one-pixel state.
//
// Layout: texel (0,0).x = preset index 0, 1 or 2 (keys 1, 2, 3); every other texel is 0.
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
    float preset = texelFetch(iChannel0, ivec2(0), 0).x;
    preset = clamp(floor(preset + 0.5), 0.0, 2.0);   // guard against anything odd in the state
    if (keyDown(49) > 0.5) preset = 0.0;            // '1' tropical ocean
    if (keyDown(50) > 0.5) preset = 1.0;            // '2' muddy river
    if (keyDown(51) > 0.5) preset = 2.0;            // '3' tannin (peat) lake
    fragColor = vec4(preset, 0.0, 0.0, 1.0);
}
