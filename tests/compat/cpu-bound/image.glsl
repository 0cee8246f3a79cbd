// Far too slow to finish a frame (hours of CPU per frame on llvmpipe): the probe is stopped by its
// CPU-time limit, whatever the machine's load, and says so.
void mainImage(out vec4 c, in vec2 f) {
    float acc = 0.0;
    for (int i = 0; i < 2000000000 + int(iTime); ++i) acc += sin(float(i) + f.x);
    c = vec4(vec3(fract(acc)), 1.0);
}
