// uniform-probe Buffer A: pixel (x, 0) holds uniform number x, raw, for tests to read back.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int x = int(fragCoord.x);
    if (int(fragCoord.y) != 0) { fragColor = vec4(-1.0); return; }
    vec4 v = vec4(0.0);
    if (x == 0) v = vec4(iResolution, 0.0);
    else if (x == 1) v = vec4(iTime, iTimeDelta, iFrameRate, float(iFrame));
    else if (x == 2) v = iMouse;
    else if (x == 3) v = iDate;
    else if (x >= 4 && x <= 7) v = vec4(iChannelResolution[x - 4], 0.0);
    else if (x == 8) v = vec4(iChannelTime[0], iChannelTime[1], iChannelTime[2], iChannelTime[3]);
    // keyboard rows for key 'A' (65): held, went down this frame, toggle
    else if (x == 9) v = vec4(iSampleRate, texelFetch(iChannel0, ivec2(65, 0), 0).x,
                              texelFetch(iChannel0, ivec2(65, 1), 0).x, texelFetch(iChannel0, ivec2(65, 2), 0).x);
    // vflip = true: texel (0,0) is the image's bottom-left pixel
    else if (x == 10) v = texelFetch(iChannel1, ivec2(0, 0), 0);
    // self feedback through a linear/clamp buffer channel: counts frames
    else if (x == 11) v = texelFetch(iChannel2, ivec2(11, 0), 0) + vec4(1.0, 0.0, 0.0, 0.0);
    fragColor = v;
}
