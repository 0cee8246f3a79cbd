// tile-probe: colour = (fragCoord.x / iResolution.x, gl_FragCoord.y / iResolution.y, 0, 1). Every
// pixel of a tiled still says where it is in the whole canvas, through mainImage's fragCoord and
// through gl_FragCoord read directly, so a tile drawn at the wrong place or with the wrong
// iResolution shows.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord.x / iResolution.x, gl_FragCoord.y / iResolution.y, 0.0, 1.0);
}
