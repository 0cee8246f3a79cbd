// sampling-probe: a stateless picture for supersampling and motion blur tests. Red and green are
// functions of fragCoord / iResolution only, with hard edges (stripes and a disc) that one sample
// per pixel stair-steps; blue is linear in iTime (0.05 per second), so the average of a shutter
// interval is known exactly.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float stripes = step(0.5, fract(uv.x * 7.3 + uv.y * 3.1));
    float disc = step(length((uv - vec2(0.6, 0.45)) * vec2(iResolution.x / iResolution.y, 1.0)), 0.3);
    fragColor = vec4(stripes, mix(uv.y, 1.0 - uv.y, disc), 0.05 * iTime, 1.0);
}
