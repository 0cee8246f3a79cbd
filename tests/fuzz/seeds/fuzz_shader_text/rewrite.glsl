float s(int n){ float a[4] = float[4](1.,2.,3.,4.); float t;
for (int i = 0; i <= n; i++) t += a[i]; vec4 v; mat3 m; return t + v[n] + m[n][n]; }
void g(out vec4 o){ lowp float packed = 1.; }
