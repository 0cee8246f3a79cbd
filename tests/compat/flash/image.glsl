// A full-screen flash: one colour at a time, changing every few frames. Valid output.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(vec3(step(0.5, fract(iTime * 4.0))), 1.0);
}
