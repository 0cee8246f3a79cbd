// Sound of cube-probe: a 440 Hz tone on the left, 660 Hz on the right, fading in over 1 s.
vec2 mainSound(in int samp, float time) {
    float fade = min(time, 1.0);
    return 0.3 * fade * vec2(sin(6.2831853 * 440.0 * time), sin(6.2831853 * 660.0 * time));
}
