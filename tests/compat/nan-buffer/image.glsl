// Reads Buffer A's alpha (a gradient) away from column 0: a right picture.
void mainImage(out vec4 c, in vec2 f) {
    c = vec4(vec3(texelFetch(iChannel0, ivec2(int(iResolution.x) - 1, int(f.y)), 0).a), 1.0);
}
