// Packed data with a NaN in one texel the picture never reads (a normalize(0) outside the drawn area).
void mainImage(out vec4 c, in vec2 f) {
    vec3 n = normalize(vec3(f.x - 0.5, 0.0, 0.0));  // 0/0 at column 0
    c = vec4(n, f.y / iResolution.y);
}
