// ripple-pool / Buffer D: the simulation's sub-step 4 of at most 4 this frame (common.glsl),
// reading Buffer C (this frame) on iChannel0.

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    rippleSubstep(fragColor, fragCoord, 3);
}
