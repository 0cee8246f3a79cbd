// Black, and slow enough (tens of ms of CPU a frame at 160x90) that the search for a fade-in
// (5 s of iTime, 300 frames) cannot finish in a few seconds of CPU time: the runner keeps the
// verdict reached after the first frames (one colour) and says the fade-in search ran out.
void mainImage(out vec4 c, in vec2 f) {
    float acc = 0.0;
    for (int i = 0; i < 3000; ++i) acc += sin(float(i) * 0.01 + f.x);
    c = vec4(vec3(step(1e30, acc)), 1.0);
}
