// uniform-probe Buffer B: samplers. Pixel (x, 0) holds probe number x.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int x = int(fragCoord.x);
    vec4 v = vec4(0.0);
    if (x == 0) v = texelFetch(iChannel0, ivec2(0, 0), 0);           // vflip false: the file's top-left
    else if (x == 1) v = texture(iChannel1, vec2(1.125, 0.25));      // repeat wrap: u = 0.125 (texel 0, exact)
    else if (x == 2) v = texture(iChannel1, vec2(0.25, 0.25));       // linear: halfway between texels 0 and 1 of the bottom row
    else if (x == 3) v = vec4(iChannelResolution[2], 0.0);           // stock RGBA Noise Small
    else if (x == 4) v = textureLod(iChannel3, vec2(0.5), 20.0);     // top mip of Buffer C: its mean
    else if (x == 5) v = texelFetch(iChannel2, ivec2(0, 0), 0);      // a noise texel (0..1)
    fragColor = v;
}
