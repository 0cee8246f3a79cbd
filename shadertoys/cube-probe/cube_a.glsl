// Cube A of cube-probe: each face holds its ray direction (rgb, as 0.5 + 0.5 * dir) blended with a
// frame counter kept in its own previous frame (alpha counts frames), so both the site's face
// corners and Cube A's feedback can be read back (--capture-pass "Cube A").
void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
    vec4 previous = texture(iChannel0, rayDir);
    fragColor = vec4(0.5 + 0.5 * rayDir, previous.a + 1.0);
}
