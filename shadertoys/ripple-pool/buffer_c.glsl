// ripple-pool / Buffer C: the simulation's sub-step 3 of at most 4 this frame (common.glsl),
// reading Buffer B (this frame) on iChannel0.

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    rippleSubstep(fragColor, fragCoord, 2);
}
