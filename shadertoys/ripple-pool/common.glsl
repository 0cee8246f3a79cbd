// ripple-pool / Common: the height-field simulation, one fixed step of which each of Buffers A-D
// may take per frame (pasted into every pass; the Image uses gridScale()).
//
// Layout of Buffers A-D (RGBA32F, each reads the one before it; A reads D of the previous frame):
//   .x  surface height h(t)      in cells (0 = calm)
//   .y  surface height h(t-1)    (the leapfrog scheme keeps two time levels)
//   .zw the pointer of the previous frame in cells (iMouse.xy / grid scale, the same in every cell), used to
//       scale drag lines by the distance the pointer moved
// Buffer D holds the state at the end of the frame; the Image reads it.
//
// Fixed step: the simulation advances SIM_RATE steps per second of iTime, whatever the frame
// rate. A frame takes the steps whose tick times fall in (iTime - iTimeDelta, iTime]: 1 at 60 fps,
// 2 at 30, 4 at 15 (fewer frames per second than 15 slow the water down), 0 or 1 above 60.
// Buffer A takes the first step (and adds the pointer's drops), B the second, C the third, D the
// fourth; a buffer with no step to take copies its input.
//
// Update (explicit leapfrog for h_tt = c^2 * laplacian(h), damped velocity):
//   h(t+1) = h + DAMPING * (h - h(t-1)) + C2 * (sum of 4 neighbours - 4h) - SPRING * h
//   C2 = c^2 = 0.45: c ~ 0.67 cells per step (40 cells/s), just inside the 2-D stability limit 0.5.
//   DAMPING = 0.995: the velocity loses 0.5% per step, ripples fade in a few s.
//   SPRING = 1e-3: a weak restoring force. Drops add water, and without it the
//   whole pool level would creep up during long drags (by ~30 cells over 1500
//   steps); with it the mean level sways slowly back to 0. It changes the
//   frequency of the ripples by under 1%, which is invisible.
// The 4 neighbour heights are sorted before they are added, so the sum is the
// same float whatever their order: a symmetric drop stays symmetric bit for bit
// under 90-degree rotations and mirrors (float addition is not associative).
// Walls: reflecting. texelFetch at a clamped coordinate returns the edge cell
// itself, i.e. a zero-slope (Neumann) boundary that mirrors waves back.
//
// Drops: a raised cosine bump A*(0.5+0.5*cos(pi*r/R)), r < R, centred exactly on
// the pointer's cell centre floor(mouse)+0.5 (r comes from integer offsets,
// so it is identical for the 4 or 8 symmetric cells). It is added to h(t) in
// full and to h(t-1) at (1 - DROP_KICK): a displacement plus a small upward
// velocity. A pure displacement leaves a deep negative dip behind the front in
// 2-D; the kick fills it, so the outgoing ring is the highest point from about
// 10 steps after the click on, moving out at a steady c.
// Full strength on the click frame (iMouse.w > 0); on later frames of a drag the
// bump is a line: the raised cosine of the distance to the segment from the
// previous pointer position to this one (a capsule), so a fast drag draws a
// continuous trough instead of a chain of stamped discs; its strength is scaled
// by the distance moved (capped at 1), so a slow drag does not pile up bumps and
// holding still adds nothing.

const float SIM_RATE  = 60.0;   // simulation steps per second of iTime
const int   MAX_STEPS = 4;      // steps a frame can take: one per buffer A-D
const float C2        = 0.45;   // (wave speed in cells per step)^2
const float DAMPING   = 0.995;  // velocity damping per step
const float SPRING    = 1e-3;   // weak pull towards h = 0 (keeps the mean level at 0)
const float DROP_R    = 8.0;    // drop radius in cells
const float DROP_AMP  = 1.0;    // drop height in cells (slopes up to ~0.2)
const float DROP_KICK = 0.2;    // fraction of the bump also given as velocity
const float DRAG_STEP = 6.0;    // a drag adds a full line every DRAG_STEP cells moved

// #define RAIN                 // deterministic automatic drops (off: tests see only the mouse)

// The simulation grid: one cell per pixel up to 180 rows; on a taller canvas the grid stays 180
// rows high (the lower-left part of the buffer) and the Image scales it up, so drops, rings and
// their speed are the same fraction of the picture at any canvas size.
float gridScale() { return max(1.0, iResolution.y / 180.0); }

// --- The view (shared by the Image and Buffer A's drops, so a click lands on the water it shows) ---
// Default: an angled 3-D view of the pool. World units are grid cells: the water is the plane
// y = 0 over x in [0, grid.x], z in [0, grid.y] (cell (i, j) is at x = i, z = j), y is up, the floor
// at y = -POOL_DEPTH * grid rows. The camera stands beyond the near long side (z < 0), CAM_PITCH
// down, placed so that the pool (rims included) is centred in the picture and its near rim just
// fits the width; its position scales with the grid, so the whole pool is in view at any aspect.
// With TOP_VIEW (--define TOP_VIEW) the Image looks straight down and pixel p is cell p / scale.
const float POOL_DEPTH = 0.36;     // pool depth, in grid rows
const float CAM_PITCH  = 0.733;    // radians down from horizontal (42 degrees)
const vec2  CAM_EYE    = vec2(1.64, -1.22);   // eye height and z, in units of the framing size
const float CAM_FOCAL  = 1.8;      // focal length in canvas heights (vertical FOV ~31 degrees)
const float RIM        = 30.0;     // the walls rise this far above the water (cells); a deck there

vec2 poolGrid() { return max(floor(iResolution.xy / gridScale()), vec2(1.0)); }

// The camera: its position and its orthonormal right, up and forward axes.
void poolCamera(out vec3 eye, out vec3 right, out vec3 up, out vec3 fwd)
{
    vec2 g = poolGrid();
    float aspect = iResolution.x / iResolution.y;
    float size = max(g.x / aspect, g.y);             // what must fit: the pool's width or depth
    fwd = vec3(0.0, -sin(CAM_PITCH), cos(CAM_PITCH));
    right = vec3(1.0, 0.0, 0.0);
    up = vec3(0.0, cos(CAM_PITCH), sin(CAM_PITCH));
    eye = vec3(0.5 * g.x, CAM_EYE * size);
}

// A sphere rests on the pool's floor and breaks the surface (--define NO_SPHERE removes it).
const float SPHERE_R = 0.25;                     // sphere radius, in grid rows
vec4 poolSphere()                                 // centre, radius
{
    vec2 g = poolGrid();
    float r = SPHERE_R * g.y;
    return vec4(0.62 * g.x, -POOL_DEPTH * g.y + r, 0.56 * g.y, r);
}

// Distance along d (unit) from o to the sphere, or -1 when it is missed (o outside the sphere).
float sphereHit(vec3 o, vec3 d)
{
#ifdef NO_SPHERE
    return -1.0;
#else
    vec4 sp = poolSphere();
    vec3 oc = o - sp.xyz;
    float b = dot(oc, d);
    float c = dot(oc, oc) - sp.w * sp.w;
    float disc = b * b - c;
    if (disc < 0.0) return -1.0;
    float t = -b - sqrt(disc);
    return t > 1e-3 ? t : -1.0;
#endif
}

// The view ray through a pixel (fragCoord in canvas pixels).
vec3 cameraRay(vec2 fragCoord, out vec3 eye)
{
    vec3 right, up, fwd;
    poolCamera(eye, right, up, fwd);
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    return normalize(fwd * CAM_FOCAL + uv.x * right + uv.y * up);
}

// The grid cell (in cells, fractional) of the water seen at pixel fragCoord; vec2(-1) where the
// pixel does not see the water (the ray misses the plane y = 0 inside the pool). Top view: the
// water is the picture, pixel / scale, never a miss (as before the 3-D view).
vec2 pixelToCell(vec2 fragCoord)
{
#ifdef TOP_VIEW
    return fragCoord / gridScale();
#else
    vec3 eye;
    vec3 d = cameraRay(fragCoord, eye);
    if (d.y >= 0.0) return vec2(-1.0);
    vec3 p = eye + d * (-eye.y / d.y);
    vec3 rim = eye + d * ((RIM - eye.y) / d.y);    // where it passes the walls' top
    vec2 g = poolGrid();
    if (p.x < 0.0 || p.z < 0.0 || p.x >= g.x || p.z >= g.y) return vec2(-1.0);
    if (rim.x < 0.0 || rim.z < 0.0 || rim.x > g.x || rim.z > g.y) return vec2(-1.0);   // behind a wall
    float ls = sphereHit(eye, d);
    if (ls > 0.0 && ls < -eye.y / d.y) return vec2(-1.0);                         // behind the sphere
    return p.xz;
#endif
}

// The tick (step number since iTime = 0) of the last step due by time t. Rounded, so that a time
// a whole number of steps long is never split by float error.
int tickAt(float t) { return int(floor(t * SIM_RATE + 0.5)); }

// The drag's capsule: raised cosine of the distance from the cell centre to the
// segment between the pointer's previous and current cell centres.
float lineShape(ivec2 cell, vec2 from, vec2 to, float radius)
{
    vec2 c = vec2(cell) + 0.5;
    vec2 ab = to - from;
    float k = clamp(dot(c - from, ab) / max(dot(ab, ab), 1e-6), 0.0, 1.0);
    float r = length(c - from - ab * k);
    if (r >= radius) return 0.0;
    return 0.5 + 0.5 * cos(3.14159265 * r / radius);
}

float dropShape(ivec2 cell, ivec2 centre, float radius)
{
    vec2 d = vec2(cell - centre);            // exact integers
    float r = sqrt(d.x * d.x + d.y * d.y);
    if (r >= radius) return 0.0;
    return 0.5 + 0.5 * cos(3.14159265 * r / radius);
}

#ifdef RAIN
float hashU(uint n)   // integer hash: the same on every GPU
{
    n = (n ^ 61u) ^ (n >> 16);
    n *= 9u;
    n ^= n >> 4;
    n *= 0x27d4eb2du;
    n ^= n >> 15;
    return float(n & 0xffffu) / 65535.0;
}
#endif

// One leapfrog step of cell p from the state in iChannel0.
vec2 waveStep(ivec2 p, ivec2 top, vec2 state)
{
    float h  = state.x;
    float h0 = state.y;
    // 4-neighbour Laplacian, reflecting walls via clamped coordinates.
    float a = texelFetch(iChannel0, clamp(p + ivec2( 1, 0), ivec2(0), top), 0).x;
    float b = texelFetch(iChannel0, clamp(p + ivec2(-1, 0), ivec2(0), top), 0).x;
    float c = texelFetch(iChannel0, clamp(p + ivec2( 0, 1), ivec2(0), top), 0).x;
    float d = texelFetch(iChannel0, clamp(p + ivec2( 0,-1), ivec2(0), top), 0).x;
    // sorting network: the sum below no longer depends on neighbour order
    float t;
    t = min(a, b); b = max(a, b); a = t;
    t = min(c, d); d = max(c, d); c = t;
    t = min(a, c); c = max(a, c); a = t;
    t = min(b, d); d = max(b, d); b = t;
    t = min(b, c); c = max(b, c); b = t;
    float nsum = ((a + b) + c) + d;
    return vec2(h + DAMPING * (h - h0) + C2 * (nsum - 4.0 * h) - SPRING * h, h);
}

// Sub-step `substep` (0 = Buffer A .. 3 = Buffer D) of this frame, reading the state in iChannel0.
void rippleSubstep(out vec4 fragColor, vec2 fragCoord, int substep)
{
    float scale = gridScale();
    ivec2 grid = max(ivec2(iResolution.xy / scale), ivec2(1));
    ivec2 p = ivec2(fragCoord);
    vec4 s = texelFetch(iChannel0, p, 0);
    int firstTick = tickAt(iTime - iTimeDelta) + 1;
    int steps = min(tickAt(iTime) - firstTick + 1, MAX_STEPS);
    if (substep > 0) {
        // later buffers: the next step if this frame has one, else the state as it is
        fragColor = (iFrame > 0 && substep < steps && all(lessThan(p, grid)))
                  ? vec4(waveStep(p, grid - 1, s.xy), s.zw) : s;
        return;
    }

    vec2 mouse = pixelToCell(iMouse.xy);            // the water under the pointer, in cells
    bool onWater = mouse.x >= 0.0;                  // (top view: always)
    if (any(greaterThanEqual(p, grid))) { fragColor = vec4(0.0, 0.0, mouse); return; }
    vec2 hn = steps > 0 ? waveStep(p, grid - 1, s.xy) : s.xy;
    if (iFrame == 0) hn = vec2(0.0);

    // The pointer's drops, once per frame; a pointer off the water drops nothing (nor does a drag
    // line from or to a point off the water).
    float bump = 0.0;
    if (iMouse.w > 0.0) {
        if (onWater) bump = DROP_AMP * dropShape(p, ivec2(floor(mouse)), DROP_R);   // click frame
    } else if (iMouse.z > 0.0 && onWater && s.z >= 0.0) {
        float strength = min(1.0, length(mouse - s.zw) / DRAG_STEP);  // drag: a line
        if (strength > 0.0)
            bump = DROP_AMP * strength * lineShape(p, floor(s.zw) + 0.5, floor(mouse) + 0.5, DROP_R);
    }
    hn += vec2(bump, bump * (1.0 - DROP_KICK));

#ifdef RAIN
    // one drop every 37 steps at a pseudo-random place (fixed by the step number)
    for (int tick = firstTick; tick < firstTick + steps; tick++) {
        if (iFrame > 0 && tick > 0 && tick % 37 == 0) {
            uint k = uint(tick / 37);
            ivec2 c0 = ivec2(vec2(hashU(2u * k), hashU(2u * k + 1u)) * (vec2(grid) - 40.0) + 20.0);
            float rain = 0.7 * DROP_AMP * dropShape(p, c0, DROP_R);
            hn += vec2(rain, rain * (1.0 - DROP_KICK));
        }
    }
#endif

    fragColor = vec4(hn, mouse);
}
