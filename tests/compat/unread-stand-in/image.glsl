// Binds a stock texture but reads it only where the mouse is pressed on the left edge, which the
// probe never does: the verdict does not depend on the stand-in.
void mainImage(out vec4 c, in vec2 f) {
    vec2 uv = f / iResolution.xy;
    c = vec4(uv, 0.5 + 0.5 * sin(iTime), 1.0);
    if (iMouse.z > 0.0 && iMouse.x < 1.0) c = texture(iChannel0, uv);
}
