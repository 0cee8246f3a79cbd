// uniform-probe Image: the newer iChN struct API and the assert helpers.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int x = int(fragCoord.x);
    vec4 v = vec4(0.0, 0.0, 0.0, 0.5);
    if (x == 0) v = vec4(iCh0.size, float(iCh0.loaded));
    else if (x == 1) v = vec4(iCh1.size, float(iCh1.loaded));
    else if (x == 2) v = vec4(iCh2.size, float(iCh2.loaded));
    else if (x == 3) v = texelFetch(iCh0.sampler, ivec2(1, 0), 0);   // = Buffer A pixel 1
    else if (x == 4) st_assert(false, 1);                            // paints green
    fragColor = v;
}
