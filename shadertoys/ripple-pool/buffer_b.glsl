// ripple-pool / Buffer B: the simulation's sub-step 2 of at most 4 this frame (common.glsl),
// reading Buffer A (this frame) on iChannel0.

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    rippleSubstep(fragColor, fragCoord, 1);
}
