// A nearly black frame (mean 0.1/255): one pixel in ten is 1/255, the rest 0. Every pixel is not
// the same colour, so "one pixel differs" called it a picture; it is empty on any screen.
void mainImage(out vec4 c, in vec2 f) {
    float lit = step(0.9, fract(sin(dot(floor(f), vec2(12.9898, 78.233))) * 43758.5453));
    c = vec4(vec3(lit / 255.0), 1.0);
}
