#define AT(i) PAL[i]
#define COL(i) MAT[i]
#define ACC float acc;
#define LOCAL(t, n) t n
#define Z 0
#define HALF round(2.5)
#define RND(x) round(x)
const float PAL[4] = float[4](1.0, 2.0, 3.0, 4.0);
const mat2 MAT = mat2(1.0);
const ivec2 CV = ivec2(7, 0);
const vec2 H = vec2(0.5, -2.5);
const int QZ = 7 / Z;
float one() { ACC acc += 1.0; LOCAL(vec2, p), q[2]; return acc + p.x + q[1]; }
void mainImage(out vec4 o, in vec2 f) {
    int k = int(f.x);
    ivec2 a = ivec2(7) / 0 + ivec2(7) % 0 + (ivec2(1) << 33) + (ivec2(-8) >> 40) + ivec2(-7) % 3;
    uvec2 b = uvec2(7u) / 0u + uvec2(7u / uint(Z));
    float c = log(-1.) + sqrt(-1.) + inversesqrt(0.) + pow(0., 0.) + atan(0., -0.) + normalize(vec3(0)).x;
    float d = round(2.5) + HALF + RND(2.5) + round(float(5) / 2.0) + round(H).y + smoothstep(1., 1., .5);
    o = vec4(AT(k) + COL(k).y + one(), float(CV.x / CV.y + QZ + a.x), float(b.y) + c, d);
}
