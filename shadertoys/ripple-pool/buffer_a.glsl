// ripple-pool / Buffer A: the simulation's sub-step 1 of at most 4 this frame (common.glsl),
// reading Buffer D (the previous frame) on iChannel0.
// It also adds the pointer's drops.

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    rippleSubstep(fragColor, fragCoord, 0);
}
