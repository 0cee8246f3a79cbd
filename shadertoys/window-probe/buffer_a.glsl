// Counts the frames since the buffers were last cleared (restart): texel (0,0).x.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = texelFetch(iChannel0, ivec2(0), 0) + vec4(1.0, 0.0, 0.0, 0.0);
}
