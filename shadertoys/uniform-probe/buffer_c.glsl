// uniform-probe Buffer C: left half 1, right half 0; read by Buffer B with mipmaps (mean 0.5).
// It also declares mediump, which desktop GPUs (and toyhost) compute in 32 bits.
precision mediump float;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    mediump float third = 1.0 / 3.0;
    fragColor = vec4(fragCoord.x < iResolution.x * 0.5 ? 1.0 : 0.0, third, 0.0, 1.0);
}
