void mainImage(out vec4 o, in vec2 fc) { float ONE = iResolution.z; float v = ((ONE * 1.001) * 1.001) + (true ? ONE : ONE + ONE);
  v = c1(v) + vec2(1.0, 2.0).y; o = vec4(v); }
float c0(float x) { return x; }
float c1(float x) { return c0(x) + 0.001; }
const float K = 1.0 + 2.0;
#define M(x) (x * K)
