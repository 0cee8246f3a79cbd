// Window-mode probe (tests/window): the input state as 8-bit colours, one value per pixel column
// at the left of the canvas (RGB only: Image's alpha is always 1); the rest of the canvas shows
// the mouse and a clock so a person sees it working. Column 0: iMouse.xy and |iMouse.z| (pixels,
// up to 255); column 1: |iMouse.w|, iMouse.z > 0, iMouse.w > 0; column 2: keyboard A held, A
// went down, A toggle; column 3: Buffer A's frame counter and iFrame (mod 256), Space held;
// column 4: iResolution.xy / 4; column 5: a constant colour that the hot-reload test edits;
// column 6: the texture probe.png (one pixel), which the hot-reload test rewrites.
float key(int code, int row) { return texelFetch(iChannel0, ivec2(code, row), 0).x; }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int column = int(fragCoord.x);
    vec3 show = 0.5 + 0.5 * cos(iTime + fragCoord.xyx / iResolution.xyx * 6.0 + vec3(0, 2, 4));
    if (iMouse.z != 0.0 && length(fragCoord - iMouse.xy) < 6.0) show = vec3(1);
    fragColor = vec4(show, 1.0);
    if (column == 0) fragColor = vec4(iMouse.xy, abs(iMouse.z), 255) / 255.0;
    else if (column == 1) fragColor = vec4(abs(iMouse.w) / 255.0, iMouse.z > 0.0, iMouse.w > 0.0, 1);
    else if (column == 2) fragColor = vec4(key(65, 0), key(65, 1), key(65, 2), 1);
    else if (column == 3)
        fragColor = vec4(mod(texelFetch(iChannel1, ivec2(0), 0).x, 256.0) / 255.0, mod(float(iFrame), 256.0) / 255.0,
                         key(32, 0), 1);
    else if (column == 4) fragColor = vec4(iResolution.xy / 4.0, 0, 255) / 255.0;
    else if (column == 5) fragColor = vec4(10, 20, 30, 255) / 255.0;
    else if (column == 6) fragColor = texelFetch(iChannel2, ivec2(0), 0);
}
