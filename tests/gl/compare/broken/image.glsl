// Does not compile: `colour' is not declared.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = colour;
}
