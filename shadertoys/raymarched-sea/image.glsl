// raymarched-sea: an open sea under a late-afternoon sky (toyhost, original work, MIT licence).
//
// Technique
// - The surface is a height field y = h(x, z): a sum of octaves of a choppy crest profile.
//   Per octave, the domain is nudged by value noise, the profile is 1 - |sin| blended with |cos|
//   (a peaked crest with a rounded trough), and the result is raised to a "choppiness" exponent
//   that starts at 4 and relaxes towards 1 (x -> mix(x, 1, 0.2)) per octave, so the big swell is
//   sharp and the ripples are soft. Each octave rotates its domain by a fixed 2x2 matrix that also
//   doubles the frequency (scale 2, angle ~34 deg, so octaves never line up); amplitude x 0.30 (0.24 read as smooth gel close up).
// - The ray is marched against only 3 octaves (cheap, and the small ones barely move the hit
//   point): from the crest plane it steps forward by the vertical gap until it is under the
//   water, then refines that bracket with Illinois false position; normals come from 6 octaves.
// - Filtering that converges to the scene (checked against ../shared/tools/gallery_truth.py,
//   TRUTH below): each octave fades once a pixel step crosses more than ~Nyquist of its domain,
//   per screen axis (a grazing pixel is a long strip along the view, a narrow one across it, so
//   octaves that run across the view keep their detail); the slope variance so lost spreads
//   Fresnel x sky over four normals (weighted by the area each shows the eye) and widens the
//   sun's glint, a unit-integral Gaussian in slope space (LEAN-style).
// - Shading (linear light): blue sky gradient with a sun glow and an HDR disc; water = deep colour
//   with wrapped diffuse + back light through thin crests, mixed with the sky reflection by
//   Schlick's Fresnel (F0 = 0.02, capped at 0.7), plus the sun's glint; exponential distance fog
//   into the horizon colour; ACES tone curve, gamma 1/2.2, fixed dither.
// - SUPERSAMPLE 2 (default) anti-aliases where it matters: 3 samples stacked along the pixel's
//   vertical axis for the pixels whose ray grazes the sea near the horizon (0.12 rad), one
//   elsewhere; 1 renders a 3x3 grid per pixel everywhere (9x the cost); 0 is one sample everywhere.
// - Camera cruises forward and turns slowly with time; dragging the mouse steers it
//   (x = heading, y = pitch).

// TRUTH (`toyhost run --define TRUTH`): the scene itself, for ../shared/tools/gallery_truth.py to
// average 16 samples of: one sample a pixel, no footprint filtering (every octave at full
// strength, the glint's lobe never widened), the quality knobs at their best. The fog stays: it
// is the scene's air.
#ifdef TRUTH
#define SUPERSAMPLE 0
#else
#define SUPERSAMPLE 2
#endif

const float EXPOSURE = 1.0;

const int   MARCH_OCTAVES = 3;
const int   SHADE_OCTAVES = 6;
#ifdef TRUTH
const int   MARCH_STEPS   = 120;
const int   REFINE_ITERS  = 8;
#else
const int   MARCH_STEPS   = 40;   // forward steps before giving up on a bracket
const int   REFINE_ITERS  = 5;
#endif

const float WAVE_HEIGHT = 0.6;   // amplitude of the first octave
const float WAVE_FREQ   = 0.16;  // spatial frequency of the first octave
const float WAVE_CHOP   = 4.0;   // choppiness exponent of the first octave
const float WAVE_SPEED  = 0.8;

// 2 * rotation(0.59 rad): doubles the frequency and turns each octave.
const mat2 OCTAVE_TURN = mat2(1.662, 1.113, -1.113, 1.662);

const vec3 SUN_DIR     = vec3(0.45, 0.2, 0.85);     // normalised where used
const vec3 DEEP_WATER  = vec3(0.004, 0.032, 0.072);  // linear colours (gamma 2.2 at the end)
const vec3 CREST_TINT  = vec3(0.177, 0.454, 0.268);
const vec3 ZENITH      = vec3(0.030, 0.130, 0.520);
const vec3 HORIZON     = vec3(0.420, 0.600, 0.860);
const vec3 SUN_RADIANCE = vec3(1.0, 0.92, 0.8) * 10.0;  // the disc's brightness in skyColor (HDR)
const float GLINT_SLOPE_VAR = 0.0025;  // the near glint's lobe: slope variance per axis (~3 degrees)
const float FADE_START = 2.0;  // an octave fades out between these radians of its domain
const float FADE_END   = 4.5;  // per pixel step (keepOctave); past Nyquist: fit to the truth

// ---------------------------------------------------------------- noise
// Integer hash of a lattice point -> [0, 1): multiply-xor the coordinates with two odd
// constants (golden-ratio and xxHash primes), then Wellons' "lowbias32" avalanche.
float latticeHash(vec2 cell) {
    uvec2 q = uvec2(ivec2(cell));
    uint h = (q.x * 0x9E3779B1u) ^ (q.y * 0x85EBCA77u);
    h ^= h >> 16; h *= 0x7FEB352Du;
    h ^= h >> 15; h *= 0x846CA68Bu;
    h ^= h >> 16;
    return float(h) * (1.0 / 4294967296.0);
}

// value noise in [-1, 1], smoothstep-faded bilinear
float valueNoise(vec2 p) {
    vec2 cell = floor(p);
    vec2 f = fract(p);
    vec2 w = f * f * (3.0 - 2.0 * f);
    float a = latticeHash(cell);
    float b = latticeHash(cell + vec2(1.0, 0.0));
    float c = latticeHash(cell + vec2(0.0, 1.0));
    float d = latticeHash(cell + vec2(1.0, 1.0));
    return 2.0 * mix(mix(a, b, w.x), mix(c, d, w.x), w.y) - 1.0;
}

// ---------------------------------------------------------------- waves
// One octave of the crest profile at domain point p with choppiness k, in [0, 1].
float crest(vec2 p, float k) {
    p += valueNoise(p);
    vec2 peak = 1.0 - abs(sin(p));       // 1 on crests, cusp-like
    vec2 round_ = abs(cos(p));           // smooth where peak is low
    vec2 prof = mix(peak, round_, peak);
    return pow(1.0 - pow(prof.x * prof.y, 0.65), k);
}

// How much of an octave survives a pixel step that crosses `phase` radians of its domain (the
// larger of the two screen axes): the octave fades to nothing past Nyquist. TRUTH: all of it.
float keepOctave(float phase) {
#ifdef TRUTH
    return 1.0;
#else
    return 1.0 - smoothstep(FADE_START, FADE_END, phase);
#endif
}

// Phase of the domain `q` (two columns: the domain's change per pixel step across and along the
// view) that one pixel step crosses, on either domain axis.
float domainPhase(mat2 q) {
    vec2 m = max(abs(q[0]), abs(q[1]));
    return max(m.x, m.y);
}

// The sea's height from `octaves` octaves. `fp` is the water one pixel step covers (columns:
// across and along the view, in xz; zero = exact): an octave whose crests a pixel step crosses
// too fast to show fades out, per screen axis, so the grazing far field keeps the octaves that
// run across the view (one width, the strip's length, flattened it to a grey mirror).
float waterHeight(vec2 xz, int octaves, mat2 fp) {
    mat2 S = mat2(0.75 * WAVE_FREQ, 0.0, 0.0, WAVE_FREQ);   // slightly longer crests across the wind
    vec2 p = S * xz;
    mat2 q = S * fp;
    float phase = 1.0 + iTime * WAVE_SPEED;
    float amp = WAVE_HEIGHT;
    float k = WAVE_CHOP;
    float h = 0.0;
    for (int i = 0; i < octaves; i++) {
        // two trains moving in opposite directions give a standing, tumbling chop
        float keep = keepOctave(domainPhase(q));
        h += amp * keep * (crest(p + phase, k) + crest(p - phase, k));
        p = OCTAVE_TURN * p;
        q = OCTAVE_TURN * q;
        amp *= 0.30;
        k = mix(k, 1.0, 0.2);
    }
    return h;
}

// Slope variance (per axis, world xz) of the octaves that footprint `fp` fades: an octave of
// amplitude a, choppiness k and domain scale f has ~2 a^2 f^2 (0.1 k + 0.1) (two trains of the
// crest profile, whose slope variance per domain unit is 0.30 at k = 1.9 .. 0.50 at k = 4,
// measured numerically); a faded octave loses (1 - keep^2) of it.
float lostSlopeVariance(mat2 fp) {
    mat2 S = mat2(0.75 * WAVE_FREQ, 0.0, 0.0, WAVE_FREQ);
    mat2 q = S * fp;
    float amp = WAVE_HEIGHT, k = WAVE_CHOP, f = WAVE_FREQ, lost = 0.0;
    for (int i = 0; i < SHADE_OCTAVES; i++) {
        float keep = keepOctave(domainPhase(q));
        lost += (1.0 - keep * keep) * 2.0 * amp * amp * f * f * (0.1 * k + 0.1);
        q = OCTAVE_TURN * q;
        amp *= 0.30;
        f *= 2.0;
        k = mix(k, 1.0, 0.2);
    }
    return lost;
}

// signed vertical distance from the surface
float above(vec3 p, int octaves) { return p.y - waterHeight(p.xz, octaves, mat2(0.0)); }

// Height-field intersection in two phases. (1) Walk forward from the crest plane with steps
// proportional to the vertical gap, divided by (|rd.y| + a slope bound) so a step cannot jump
// through a wave; the steps grow with distance, so far rays reach the horizon in a few dozen
// samples. (2) Once a sample lands under the water, refine the bracket with Illinois false
// position (the stale end's value is halved so it cannot stall). Returns t; hit = found water.
float traceSea(vec3 ro, vec3 rd, out bool hit) {
    const float FAR = 1000.0;
    float topY = 2.6 * WAVE_HEIGHT;                 // above any crest the march octaves make
    hit = false;
    float tLo = 0.0;
    if (ro.y > topY) {
        if (rd.y >= 0.0) return FAR;
        tLo = (ro.y - topY) / -rd.y;
    }
    float fLo = above(ro + rd * tLo, MARCH_OCTAVES);
    float tHi = tLo, fHi = fLo;
    float stepScale = 1.0 / (abs(rd.y) + 0.6);
    for (int i = 0; i < MARCH_STEPS; i++) {
        tHi = tLo + max(fLo * stepScale, 0.002 * tLo + 0.02);
        fHi = above(ro + rd * tHi, MARCH_OCTAVES);
        if (fHi < 0.0) { hit = true; break; }
        tLo = tHi; fLo = fHi;
        if (tLo > FAR) return FAR;
    }
    if (!hit) {
        // ran out of steps while still above: try one long bracket to the far distance
        tHi = FAR;
        fHi = above(ro + rd * tHi, MARCH_OCTAVES);
        if (fHi >= 0.0) return FAR;
        hit = true;
    }
    int side = 0;
    float t = tHi;
    for (int i = 0; i < REFINE_ITERS; i++) {
        t = (tLo * fHi - tHi * fLo) / (fHi - fLo);
        float f = above(ro + rd * t, MARCH_OCTAVES);
        if (f < 0.0) {
            tHi = t; fHi = f;
            if (side == -1) fLo *= 0.5;
            side = -1;
        } else {
            tLo = t; fLo = f;
            if (side == 1) fHi *= 0.5;
            side = 1;
        }
    }
    return t;
}

vec3 waterNormal(vec3 p, mat2 fp) {
    const float eps = 0.002;
    float hx = waterHeight(p.xz + vec2(eps, 0.0), SHADE_OCTAVES, fp) - waterHeight(p.xz - vec2(eps, 0.0), SHADE_OCTAVES, fp);
    float hz = waterHeight(p.xz + vec2(0.0, eps), SHADE_OCTAVES, fp) - waterHeight(p.xz - vec2(0.0, eps), SHADE_OCTAVES, fp);
    return normalize(vec3(-hx, 2.0 * eps, -hz));
}

// ---------------------------------------------------------------- lighting
vec3 skyColor(vec3 rd) {
    vec3 sun = normalize(SUN_DIR);
    float up = max(rd.y, 0.0);
    vec3 col = mix(HORIZON, ZENITH, pow(up, 0.45));
    float mu = max(dot(rd, sun), 0.0);
    col += vec3(1.0, 0.72, 0.42) * (0.25 * pow(mu, 6.0) + 0.35 * pow(mu, 90.0));
    col += SUN_RADIANCE * smoothstep(0.99975, 0.99988, mu);   // the disc
    return col;
}

// `unseen`: the slope variance (per axis) the pixel does not show (faded octaves, variation
// inside the pixel). Fresnel x sky is averaged over four normals spread by it, each weighted by
// the area it shows the eye (at grazing views the faces turned to the eye fill the pixel, with a
// lower Fresnel than a flat mirror's). The sun's glint is a Gaussian in slope space (LEAN-style)
// around the slope that mirrors the sun, of the near lobe's variance plus `unseen`, with unit
// integral: a wider, dimmer glint where detail was filtered, the same energy as the truth's.
vec3 shadeWater(vec3 p, vec3 n, vec3 rd, float unseen) {
    vec3 sun = normalize(SUN_DIR);
    vec2 slope = -n.xz / n.y;
    vec2 along = normalize(rd.xz + vec2(1e-6, 0.0));
    vec2 across = vec2(-along.y, along.x);
    float sigma = sqrt(unseen);
    float F = 0.0, area = 0.0;
    vec3 refl = vec3(0.0);
    for (int k = 0; k < 4; k++) {
        vec2 o = vec2(k & 1, k >> 1) * 2.0 - 1.0;
        vec2 sk = slope + sigma * (o.x * along + o.y * across);
        vec3 nk = normalize(vec3(-sk.x, 1.0, -sk.y));
        float cosV = clamp(dot(nk, -rd), 0.0, 1.0);
        float seen = cosV / nk.y;
        float Fk = 0.02 + 0.98 * pow(1.0 - cosV, 5.0);   // Schlick, water F0 ~ 0.02
        Fk = min(Fk, 0.7);                                 // grazing: keep some body colour
        vec3 rk = reflect(rd, nk);
        rk.y = abs(rk.y);
        refl += seen * Fk * skyColor(rk);
        F += seen * Fk;
        area += seen;
        if (unseen == 0.0) break;                          // one normal: the taps would agree
    }
    refl /= max(F, 1e-6);
    F /= max(area, 1e-6);

    float wrapDiff = pow(dot(n, sun) * 0.4 + 0.6, 40.0);
    vec3 body = DEEP_WATER + 0.15 * wrapDiff * CREST_TINT;

    // back light: sun through the thin top of a crest, seen against the light
    float crestAmt = clamp(p.y / (2.0 * WAVE_HEIGHT), 0.0, 1.0);
    float against = pow(max(dot(rd, sun), 0.0), 2.0) * (1.0 - 0.5 * max(n.y, 0.0));
    body += CREST_TINT * 0.3 * crestAmt * crestAmt * (0.3 + against);

    vec3 col = mix(body, refl, F);

    vec3 h = normalize(sun - rd);
    vec2 toSun = -h.xz / h.y - slope;
    float lobe = GLINT_SLOPE_VAR + unseen;
    float spec = GLINT_SLOPE_VAR / lobe * exp(-0.5 * dot(toSun, toSun) / lobe) * max(dot(n, sun), 0.0);
    col += SUN_RADIANCE * spec * F;

    return col;
}

mat3 lookBasis(float yaw, float pitch) {
    vec3 fwd = vec3(sin(yaw) * cos(pitch), sin(pitch), cos(yaw) * cos(pitch));
    vec3 right = normalize(cross(vec3(0.0, 1.0, 0.0), fwd));
    vec3 up = cross(fwd, right);
    return mat3(right, up, fwd);
}

// The camera's ray through fragCoord.
void viewRay(vec2 fragCoord, out vec3 ro, out vec3 rd, out mat3 cam) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;

    // slow orbit: the heading turns with time while the boat cruises along it
    float t = iTime;
    float yaw = 0.6 * sin(t * 0.06);
    float pitch = -0.16 + 0.02 * sin(t * 0.5);
    if (iMouse.z > 0.0) {
        vec2 m = iMouse.xy / iResolution.xy - 0.5;
        yaw += m.x * 3.0;
        pitch = clamp(-0.16 + m.y * 1.2, -0.9, 0.4);
    }
    ro = vec3(30.0 * sin(t * 0.04), 3.4 + 0.15 * sin(t * 0.8), 5.0 * t);
    cam = lookBasis(yaw, pitch);
    rd = normalize(cam * vec3(uv, 2.0));
}

// `along`: the share of the pixel's height this sample stands for (1: the whole pixel; 1/3: one
// of three samples stacked along the view, which average the rest of it).
vec3 render(vec2 fragCoord, float along) {
    vec3 ro, rd;
    mat3 cam;
    viewRay(fragCoord, ro, rd, cam);
    vec3 sky = skyColor(rd);
    bool hit;
    float dist = traceSea(ro, rd, hit);
    if (!hit) return sky;

    vec3 p = ro + rd * dist;
    // the water one pixel step covers, across the view (the camera's right axis) and along it
    // (its up axis projected onto the water, stretched by the grazing angle)
#ifdef TRUTH
    mat2 fp = mat2(0.0);
#else
    vec3 up = cam[1] - rd * (cam[1].y / min(rd.y, -0.02));
    mat2 fp = dist / iResolution.y * mat2(cam[0].xz, along * up.xz);
#endif
    vec3 n = waterNormal(p, fp);
    vec3 col = shadeWater(p, n, rd, lostSlopeVariance(fp));

    float fog = 1.0 - exp(-dist * 0.0045);
    return mix(col, skyColor(normalize(vec3(rd.x, 0.0, rd.z))) , fog * fog);
}

// ACES filmic tone curve (Stephen Hill's fitted RRT + ODT, sRGB primaries in and out)
vec3 acesFitted(vec3 c) {
    const mat3 toAces = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 fromAces = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    c = toAces * c;
    vec3 a = c * (c + 0.0245786) - 0.000090537;
    vec3 b = c * (0.983729 * c + 0.4329510) + 0.238081;
    return clamp(fromAces * (a / b), 0.0, 1.0);
}

// Triangular dither of +-1 code value per channel, fixed per pixel (the same every frame, so it
// neither flickers nor changes a golden frame): turns the 8-bit steps of smooth gradients into
// grain. Two uniform hashes per channel (one 3-vector hash of the pixel, another of a shifted one).
vec3 ditherNoise(vec2 fragCoord) {
    vec3 p = fract(vec3(fragCoord.xyx) * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    vec3 a = fract((p.xxy + p.yzz) * p.zyx);
    vec3 q = fract(vec3(fragCoord.yxy + 17.0) * vec3(0.1031, 0.1030, 0.0973));
    q += dot(q, q.yxz + 33.33);
    vec3 b = fract((q.xxy + q.yzz) * q.zyx);
    return (a + b - 1.0) / 255.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
#if SUPERSAMPLE == 1
    vec3 col = vec3(0.0);
    for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++)
            col += render(fragCoord + vec2(i, j) / 3.0, 1.0);
    col /= 9.0;
#elif SUPERSAMPLE == 2
    // adaptive: 3 samples stacked along the pixel's vertical axis only where the ray grazes the
    // sea near the horizon (the crest silhouettes alias there, which no prefilter predicts: ~10%
    // of the pixels; 0.06 rad left the far band at 28 dB against the truth, 0.12 gives 30); one
    // sample elsewhere. A grazing pixel is a long strip of water along the view and a narrow one
    // across it, so the samples go along it, each filtering a third of the strip (4 rotated-grid
    // samples gave 31.1 / 30.3 dB in the far band at t = 3 / 6, these 3 give 31.5 / 30.5)
    vec3 ro, rd;
    mat3 cam;
    viewRay(fragCoord, ro, rd, cam);
    int samples = (rd.y > -0.12 && rd.y < 0.01) ? 3 : 1;
    // The loop tests at its bottom: llvmpipe runs a loop's body once more than its count when the
    // test is at the top (a whole render at every pixel), and an if's body for every pixel
    // (docs/performance.md); this way only the band's pixels pay for their second and third.
    vec3 col = vec3(0.0);
    for (int k = 0; k < 3; k++) {
        float y = samples == 1 ? 0.0 : (float(k) + 0.5) / float(samples) - 0.5;
        col += render(fragCoord + vec2(0.0, y), 1.0 / float(samples));
        if (k + 1 >= samples) break;
    }
    col /= float(samples);
#else
    vec3 col = render(fragCoord, 1.0);
#endif
    col = acesFitted(col * EXPOSURE);                    // tone map: the sun rolls off, no clipping
    fragColor = vec4(pow(col, vec3(1.0 / 2.2)) + ditherNoise(fragCoord), 1.0);
}
