// Image of cube-probe: a sphere reflecting Cube A (the ray colours) in front of the stock
// "Forest" cubemap (a stand-in sky without the real files), a noise volume slice and a video
// strip at the bottom.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 rd = normalize(vec3(p, -1.5));
    float a = 0.3 * iTime;
    rd.xz = mat2(cos(a), -sin(a), sin(a), cos(a)) * rd.xz;
    vec3 col = texture(iChannel1, rd).rgb;
    float b = dot(p, p);
    if (b < 0.36) {
        vec3 n = normalize(vec3(p, sqrt(0.36 - b)));
        col = texture(iChannel0, reflect(vec3(0.0, 0.0, -1.0), n)).rgb;
    }
    if (fragCoord.y < 0.2 * iResolution.y) {
        vec2 uv = fragCoord / iResolution.xy;
        col = uv.x < 0.5 ? texture(iChannel2, vec3(2.0 * uv.x, 5.0 * uv.y, 0.1 * iTime)).rrr
                         : texture(iChannel3, vec2(2.0 * uv.x - 1.0, 5.0 * uv.y)).rgb;
    }
    fragColor = vec4(col, 1.0);
}
