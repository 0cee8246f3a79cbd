// White noise in every channel: the incompressible worst case for the PNG encoder benchmark.
uint mixBits(uint x) {
    x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
    return x;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uvec2 q = uvec2(fragCoord);
    uint h = mixBits(q.x + mixBits(q.y + mixBits(uint(iFrame))));
    fragColor = vec4(uvec4(h, h >> 8, h >> 16, h >> 24) & 255u) / 255.0;
}
