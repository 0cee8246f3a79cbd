// tile-probe: colour = (fragCoord / iResolution, 0, 1). Every pixel of a tiled still says where it
// is in the whole canvas, so a tile drawn at the wrong place or with the wrong iResolution shows.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(fragCoord / iResolution.xy, 0.0, 1.0);
}
