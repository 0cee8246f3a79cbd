void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 a = fetch(iChannel0, fragCoord);
    vec4 b = fetch(iChannel1, fragCoord);
    fragColor = vec4(a.x / 100.0, b.x / 1000.0, b.y / 1000.0, 0.3);
}
