// Buffer A holds alpha 0.25 everywhere; Image shows only its colour (alpha forced to 1).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord / iResolution.xy, 0.0, 0.25);
}
