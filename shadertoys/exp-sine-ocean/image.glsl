// exp-sine-ocean: a sunlit ocean of sharp-crested waves (toyhost, original work, MIT licence).
//
// Technique
// - Each wave is exp(sin(x) - 1): in (e^-2, 1], with narrow peaked crests and wide flat troughs,
//   like real deep-water waves. The surface sums many of them, each turned by the golden angle
//   (2.39996 rad) so no two directions line up, with frequency x1.18, speed x1.07 and weight x0.8
//   per wave.
// - Drag (domain warping): after each wave the sample point moves along that wave's direction by
//   its slope d/dx exp(sin x - 1) = exp(sin x - 1) cos x, times the wave's weight and DRAG (0.38).
//   Later, smaller waves are thereby pulled into the crests of earlier ones, which bunches
//   ripples on the crests and leaves the troughs smooth.
// - The normalised sum lies in (0, 1]; the surface is 0 .. -DEPTH below y = 0, so the ray is only
//   marched between the planes y = 0 and y = -DEPTH, in steps of the vertical gap over the
//   steepest rise the water is assumed to have, then refined by false position once it is under
//   the water. The march meets 16 waves near the horizon and 12 below, the slope 24 (extra detail
//   only in shading), computed exactly through the drag's chain rule.
// - Filtering that converges to the scene (checked against ../shared/tools/gallery_truth.py,
//   TRUTH below). Near the horizon a pixel covers a long strip of water along the view and a
//   narrow one across it, and which crest each part of the strip shows is beyond any prefilter:
//   there 3 (6 in the top rows) samples stacked along the pixel's vertical axis average it, the
//   later ones marching on from where the steeper one below met the water. Across the view, and
//   everywhere in the one-sample water below, each wave of the slope fades to its mean once the
//   phase one pixel step crosses nears Nyquist. The slopes so lost (their covariance), the
//   slope variation still inside a one-sample pixel (screen derivatives) and the capillary
//   ripples shorter than any modelled wave (Cox & Munk) make the reflection a lobe: Fresnel x
//   sky is averaged over four normals spread by that variance, weighted by the area each shows
//   the eye; and the sun's glitter is a LEAN-style Gaussian in slope space widened by the same
//   covariance.
// - Sky: single-scattering air with a per-channel Rayleigh optical depth along an air mass of
//   1 / (sin(elevation) + 0.1): deep blue overhead, whitening towards the horizon, plus a sun glow.
// - Shading: Schlick's Fresnel with F0 = 0.04 mixes a sky reflection (which carries a bright HDR
//   sun, hence the glitter path) with a subsurface tint, stronger in the troughs than on the
//   crests; ACES filmic curve (Stephen Hill's fitted RRT+ODT), then gamma 1/2.2 and a fixed
//   +-1 level triangular dither (no 8-bit bands in smooth gradients, the same every frame).
// - Camera: fixed above the water; before any click it looks at the horizon. Click or drag: look
//   where the mouse is (x = heading, full turn across the width; y = pitch, centre = default).

// TRUTH (`toyhost run --define TRUTH`): the scene itself, for ../shared/tools/gallery_truth.py to
// average 16 samples of: no footprint filtering (every wave at full strength, no lobe widening),
// the quality knobs at their best. The haze and the capillary roughness stay: they are the scene.
const float DEPTH        = 1.0;    // wave range: the surface stays within [-DEPTH, 0]
const float DRAG         = 0.38;
#ifdef TRUTH
const int   FAR_WAVES    = 16;     // waves the march meets in the far band (see FAR_STRIP) ...
const int   NEAR_WAVES   = 16;     // ... and below it
const int   NORMAL_WAVES = 40;
const int   MARCH_STEPS  = 160;
const float MARCH_SLOPE  = 0.6;    // the steepest rise of the water a step assumes (see marchWater)
const float MARCH_MIN_PIXELS = 0.0; // the shortest step, in pixels of footprint along the ray
const float FAR_STRIP    = 1e30;   // one sample a pixel everywhere (the tool averages 16)
#else
const int   FAR_WAVES    = 16;     // the truth's: a grazing ray's hit moves with every wave
const int   NEAR_WAVES   = 12;     // steeper rays (the seed's count): 16 cost 1.4x the frame for +1.3 dB
const int   NORMAL_WAVES = 24;     // more only alias in the far band (the truth keeps 40)
const int   MARCH_STEPS  = 48;
const float MARCH_SLOPE  = 0.2;
const float MARCH_MIN_PIXELS = 0.1;
const float FAR_STRIP    = 0.15;   // pixels whose strip of water along the view (units of DEPTH) is
                                   // longer take FAR_SAMPLES (-rd.y < 0.2 at 640x360)
#endif
const int   FAR_SAMPLES  = 3;      // samples stacked along the view in the far band ...
const float HORIZON_STRIP = 1.6;   // ... and its top rows, strips longer than this (3 samples
const int   HORIZON_SAMPLES = 6;   // alias there: detail 1.5-2 against the truth)
const int   MARCH_REFINE = 3;      // false-position steps once the ray has crossed the surface
const float CAMERA_Y     = 1.2;    // above the top plane
const float GLINT_SLOPE_VAR = 2.8e-4; // the near glitter lobe: slope variance per axis (~1 degree)
const float FADE_START   = 1.0;    // a wave fades to its mean between these radians of phase
const float FADE_END     = 3.0;    // per pixel step (keepWave)
const float PIXEL_VAR_SCALE = 0.25; // slope variance inside a pixel per (slope step per pixel)^2
const float WAVE_SLOPE_VAR = 0.1076; // variance of d/dx exp(sin x - 1) over a period
// Slope variance (both axes) of the capillary ripples no wave here models: Cox & Munk's clean
// minus slick sea surface (0.0033 per m/s of wind) at a fresh breeze of ~9 m/s.
const float CAPILLARY_SLOPE_VAR = 0.03;

const vec3  SUN_DIR      = vec3(0.25, 0.1, 1.0);           // normalised where used
const vec3  TROUGH_TINT  = vec3(0.008, 0.040, 0.060);      // subsurface colour in the troughs
const float CREST_TINT   = 0.35;                           // ... scaled this much on crests

// 2x2 rotation by the golden angle, applied to the wave direction after every wave
const mat2 GOLDEN_TURN = mat2(-0.737369, 0.675490, -0.675490, -0.737369);

// How much of a wave survives a pixel's footprint: `phase` is the radians of the wave's phase
// that one pixel step crosses (the larger of the two screen axes). A box average over the pixel
// keeps sinc(phase / 2) of a sinusoid; past Nyquist (pi) a point sample can only alias it, so the
// wave goes to its mean between FADE_START and FADE_END.
float keepWave(float phase) {
#ifdef TRUTH
    return 1.0;
#else
    return 1.0 - smoothstep(FADE_START, FADE_END, phase);
#endif
}

// Phase a wave of direction `dir` and frequency `freq` crosses per pixel step, from the footprint
// `fp` (columns: the water one pixel step moves across and along the view, in xz).
float phasePerPixel(vec2 dir, float freq, mat2 fp) {
    return freq * max(abs(dot(dir, fp[0])), abs(dot(dir, fp[1])));
}

// Height of the water at xz in [-DEPTH, 0], from the first n waves at full strength (what the
// march meets): the normalised sum of the waves, 1 = highest crest.
float surfaceY(vec2 xz, int n) {
    vec2 dir = vec2(1.0, 0.0);
    float freq = 1.0, speed = 2.0, weight = 1.0, sum = 0.0, total = 0.0;
    for (int i = 0; i < n; i++) {
        float x = dot(dir, xz) * freq + iTime * speed;
        float w = exp(sin(x) - 1.0);
        xz += dir * w * cos(x) * weight * DRAG;   // drag: pull later waves toward this crest
        sum += w * weight;
        total += weight;
        weight *= 0.8;
        freq *= 1.18;
        speed *= 1.07;
        dir = GOLDEN_TURN * dir;
    }
    return (sum / total - 1.0) * DEPTH;
}

// The slope (dy/dx, dy/dz) of the water at xz from the NORMAL_WAVES waves, each faded by what the
// pixel's footprint `fp` can hold (zero footprint: exact), and the slope covariance the faded
// waves lose. The footprint is anisotropic: at a grazing view a pixel covers a long strip of
// water along the view and a narrow one across it, so waves whose crests run across the view
// fade long before waves whose crests point at the eye (a single width, the strip's length,
// erased the far water's detail). The slope is exact (no finite differences): the chain rule
// through the drag, whose Jacobian `warp` (d xz / d xz at the start) grows with every wave.
// Lost covariance: each wave's slope amplitude is weight x frequency / total weight along its
// direction, and a wave faded by `keep` keeps keep^2 of its variance.
vec2 waterSlope(vec2 xz, mat2 fp, out mat2 lost) {
    vec2 dir = vec2(1.0, 0.0);
    float freq = 1.0, speed = 2.0, weight = 1.0, total = 0.0;
    vec2 grad = vec2(0.0);
    mat2 warp = mat2(1.0);
    lost = mat2(0.0);
    for (int i = 0; i < NORMAL_WAVES; i++) {
        float x = dot(dir, xz) * freq + iTime * speed;
        float keep = keepWave(phasePerPixel(dir, freq, fp));
        float sx = sin(x), cx = cos(x);
        float w = exp(sx - 1.0);
        vec2 dx = freq * (dir * warp);            // d x / d xz at the start
        grad += weight * keep * w * cx * dx;      // d w / d x = w cos x
        float drag = weight * DRAG * keep;
        xz += dir * (w * cx * drag);
        warp += outerProduct(dir, (w * (cx * cx - sx) * drag) * dx);   // d (w cos x) / d x
        lost += weight * weight * freq * freq * (1.0 - keep * keep) * outerProduct(dir, dir);
        total += weight;
        weight *= 0.8;
        freq *= 1.18;
        speed *= 1.07;
        dir = GOLDEN_TURN * dir;
    }
    lost *= WAVE_SLOPE_VAR / (total * total);
    return grad * (DEPTH / total);
}

// March between the planes y = 0 and y = -DEPTH. A step is the vertical gap over the steepest rise
// of the water it assumes (MARCH_SLOPE) plus the ray's own descent: at grazing angles the ray runs
// almost parallel to the water, and a gap-sized step (the seed's) crawls, so 48 of them ended above
// the far water. A rarer steeper face is crossed, not missed: once the ray is below the surface,
// MARCH_REFINE false-position steps between the last point above and the first below find it.
// Steps are also at least MARCH_MIN_PIXELS of the pixel's footprint along the ray (no crest
// thinner than that is missed in a way a pixel could show). `hStart`: the horizontal distance of a
// hit already known nearer on this ray's vertical plane (a steeper ray of the same pixel column
// meets the height field no further away), where the march may begin; 0: from the top plane.
// `waves`: how many waves of the height field the march meets.
float marchWater(vec3 ro, vec3 rd, float hStart, int waves) {
    float tTop = ro.y / -rd.y;
    float tBot = (ro.y + DEPTH) / -rd.y;
    float t = clamp(hStart / length(rd.xz), tTop, tBot);
    float gapPrev = ro.y + rd.y * t - surfaceY((ro + rd * t).xz, waves);
    if (gapPrev < 0.0) {                                   // under a crest already: from the top
        t = tTop;
        gapPrev = ro.y + rd.y * t - surfaceY((ro + rd * t).xz, waves);
    }
    float tPrev = t, gap = gapPrev;
    float stretch = 1.0 / (MARCH_SLOPE + abs(rd.y));
    float pixelAngle = 2.0 / (iResolution.y * 1.6);
    float minStep = max(0.001, MARCH_MIN_PIXELS * pixelAngle / max(-rd.y, 0.005));   // x t
    for (int i = 0; i < MARCH_STEPS; i++) {
        t = min(t + max(gapPrev * stretch, minStep * t), tBot);
        gap = ro.y + rd.y * t - surfaceY((ro + rd * t).xz, waves);
        if (gap < 0.0 || t >= tBot) break;
        tPrev = t;
        gapPrev = gap;
    }
    if (gap >= 0.0) return t;
    float a = tPrev, ga = gapPrev, b = t, gb = gap;
    for (int k = 0; k < MARCH_REFINE; k++) {
        float m = mix(a, b, ga / max(ga - gb, 1e-6));
        float gm = ro.y + rd.y * m - surfaceY((ro + rd * m).xz, waves);
        if (gm < 0.0) { b = m; gb = gm; } else { a = m; ga = gm; }
    }
    return mix(a, b, ga / max(ga - gb, 1e-6));
}

// The water one pixel step covers at distance `dist` along `rd`, as two xz vectors (columns):
// across the view (the camera's right axis) and along it (its up axis, projected onto the water
// plane, stretched by the grazing angle), the latter scaled by `along` (0 where samples stacked
// along the view already average that axis). TRUTH: none.
mat2 pixelFootprint(float dist, vec3 rd, mat3 cam, float along) {
#ifdef TRUTH
    return mat2(0.0);
#else
    float pixelAngle = 2.0 / (iResolution.y * 1.6);
    vec3 up = cam[1] - rd * (cam[1].y / min(rd.y, -0.02));
    return dist * pixelAngle * mat2(cam[0].xz, along * up.xz);
#endif
}

// The air: light scattered once towards the eye, with a Rayleigh optical depth per channel (blue
// scatters most) along an air mass of 1 / (sin(elevation) + 0.1) (bounded at the horizon), plus
// the glow around the sun. No sun disc: see sky().
vec3 skyAir(vec3 rd) {
    const vec3 RAYLEIGH_DEPTH = vec3(0.13, 0.30, 0.68);   // at the zenith, ~ 1 / wavelength^4
    vec3 sun = normalize(SUN_DIR);
    float airMass = 1.0 / (max(rd.y, 0.0) + 0.1);
    vec3 col = 0.75 * (1.0 - exp(-RAYLEIGH_DEPTH * airMass));
    float mu = max(dot(rd, sun), 0.0);
    col += vec3(1.0, 0.62, 0.28) * (0.18 * pow(mu, 16.0) + 0.8 * pow(mu, 300.0));
    return col;
}

vec3 sky(vec3 rd) {
    float mu = max(dot(rd, normalize(SUN_DIR)), 0.0);
    return skyAir(rd) + vec3(1.0, 0.80, 0.55) * 40.0 * smoothstep(0.99988, 0.99993, mu);   // HDR disc
}

// ACES filmic tone curve, Stephen Hill's fit of the RRT + ODT (sRGB primaries in and out)
vec3 acesFitted(vec3 c) {
    const mat3 toAces = mat3(0.59719, 0.07600, 0.02840,
                             0.35458, 0.90834, 0.13383,
                             0.04823, 0.01566, 0.83777);
    const mat3 fromAces = mat3( 1.60475, -0.10208, -0.00327,
                               -0.53108,  1.10813, -0.07276,
                               -0.07367, -0.00605,  1.07602);
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

mat3 viewBasis(float yaw, float pitch) {
    vec3 f = vec3(sin(yaw) * cos(pitch), sin(pitch), cos(yaw) * cos(pitch));
    vec3 r = normalize(cross(vec3(0.0, 1.0, 0.0), f));
    return mat3(r, cross(f, r), f);
}

vec3 viewRay(vec2 fragCoord, mat3 cam) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    return normalize(cam * vec3(uv, 1.6));
}

// What one sample sees: the view ray, where it meets the water, the slope there that the pixel's
// footprint leaves (the waves it cannot show faded to their mean) and the slope covariance lost.
struct Sample { vec3 rd; bool water; float dist; vec3 p; vec2 slope; mat2 lost; };

Sample traceSample(vec3 ro, vec3 rd, mat3 cam, bool far, float hStart) {
    Sample s = Sample(rd, rd.y < 0.0, 0.0, ro, vec2(0.0), mat2(0.0));
    if (s.water) {
        s.dist = marchWater(ro, rd, hStart, far ? FAR_WAVES : NEAR_WAVES);
        s.p = ro + rd * s.dist;
        s.slope = waterSlope(s.p.xz, pixelFootprint(s.dist, rd, cam, far ? 0.0 : 1.0), s.lost);
    }
    return s;
}

// The sample's colour after the tone curve (display light, before gamma). `pixelVar`: the slope
// variance still inside the pixel.
vec3 shadeSample(Sample s, float pixelVar) {
    mat2 lost = s.lost;
    vec3 rd = s.rd;
    vec3 col;
    if (!s.water) {
        col = sky(rd);
    } else {
        // Fresnel x sky over the slopes this sample does not resolve (the faded waves' covariance,
        // the variation inside the pixel and the capillaries): four normals, the slopes moved by
        // +-sigma along and across the view. Each is weighted by the area it shows the eye (cos
        // to the eye / cos to the vertical): at grazing views the faces turned towards the eye
        // fill the pixel, and their Fresnel is lower than a flat sheet's. The sun disc is left to
        // the glitter lobe below (four taps cannot sample a disc this small).
        vec2 along = normalize(rd.xz + vec2(1e-6, 0.0));
        vec2 across = vec2(-along.y, along.x);
        float lostAlong = dot(along, lost * along) + 0.5 * pixelVar;
        float lostAcross = dot(across, lost * across) + 0.5 * pixelVar;
        vec2 sigma = sqrt(vec2(lostAlong, lostAcross) + 0.5 * CAPILLARY_SLOPE_VAR);
        float F = 0.0, area = 0.0;
        vec3 refl = vec3(0.0);
        for (int k = 0; k < 4; k++) {
            vec2 o = vec2(k & 1, k >> 1) * 2.0 - 1.0;
            vec2 sk = s.slope + o.x * sigma.x * along + o.y * sigma.y * across;
            vec3 nk = normalize(vec3(-sk.x, 1.0, -sk.y));
            float seen = max(dot(nk, -rd), 0.0) / nk.y;
            float Fk = 0.04 + 0.96 * pow(1.0 - max(dot(nk, -rd), 0.0), 5.0);   // Schlick, F0 = 0.04
            vec3 rk = reflect(rd, nk);
            rk.y = abs(rk.y);                             // no reflections from below the horizon
            refl += seen * Fk * skyAir(rk);
            F += seen * Fk;
            area += seen;
        }
        refl /= max(F, 1e-6);                             // the Fresnel-weighted mean sky
        F /= max(area, 1e-6);

        // The sun's glitter, LEAN-style: a wave facet mirrors the sun where its slope equals the
        // half vector's; the lobe is a Gaussian in slope space around that slope, of the near
        // lobe's variance (GLINT_SLOPE_VAR) plus every slope this sample does not show (the faded
        // waves' covariance and the variation inside the pixel). Its peak falls as the lobe
        // widens (unit integral), so the glitter path keeps its energy.
        vec3 h = normalize(normalize(SUN_DIR) - rd);
        vec2 toSun = -h.xz / h.y - s.slope;
        mat2 lobe = lost + (GLINT_SLOPE_VAR + 0.5 * pixelVar) * mat2(1.0);
        float glint = GLINT_SLOPE_VAR / sqrt(determinant(lobe)) * exp(-0.5 * dot(toSun, inverse(lobe) * toSun));
        refl += vec3(1.0, 0.75, 0.45) * 30.0 * glint;

        // subsurface: light scattered back out of the water, deepest in the troughs
        float crest = clamp((s.p.y + DEPTH) / DEPTH, 0.0, 1.0);
        vec3 sss = TROUGH_TINT * mix(1.0, CREST_TINT, crest);

        col = F * refl + (1.0 - F) * sss;
        // faraway water fades into the horizon haze
        col = mix(col, sky(normalize(vec3(rd.x, 0.0, rd.z))), 1.0 - exp(-s.dist * 0.002));
    }
    return acesFitted(col * 1.1);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    // Before the first click iMouse is all zeros: default horizon view, which is also what the
    // mouse at the centre of the canvas gives.
    vec2 m = vec2(0.5);
    if (iMouse.z > 0.0 || any(notEqual(iMouse, vec4(0.0)))) m = iMouse.xy / iResolution.xy;
    float yaw = (m.x - 0.5) * 6.2831853;
    float pitch = clamp((m.y - 0.5) * 2.6 - 0.1, -1.4, 1.4);
    vec3 ro = vec3(0.0, CAMERA_Y, 0.0);
    mat3 cam = viewBasis(yaw, pitch);

    // The far band, just under the horizon: a pixel there covers a long strip of water along the
    // view, and which crest each part of it shows is beyond any prefilter (the footprint fades
    // and lobes gave a darker, blurrier band than the truth). FAR_SAMPLES rays (HORIZON_SAMPLES in
    // its top rows) stacked along the pixel's vertical axis sample it instead, footprint-filtered
    // across the view only; each starts its march where the steeper one below met the water.
    // Elsewhere one sample.
    vec3 rdCentre = viewRay(fragCoord, cam);
    // The strip a pixel covers along the view on flat water at the mean level, of the ray's
    // distance x pixel angle / grazing sine: the same strip takes the same samples at any size.
    float grazing = max(-rdCentre.y, 1e-4);
    float strip = (CAMERA_Y + 0.5 * DEPTH) / grazing * (2.0 / (iResolution.y * 1.6)) / grazing;
    bool far = rdCentre.y < 0.0 && strip > FAR_STRIP;
    int samples = far ? (strip > HORIZON_STRIP ? HORIZON_SAMPLES : FAR_SAMPLES) : 1;
    float step = 1.0 / float(samples);

    // The first sample comes in uniform control flow, so that its slope's screen derivatives
    // (below) are defined in every pixel of a quad.
    Sample s = traceSample(ro, viewRay(fragCoord + vec2(0.0, 0.5 * step - 0.5), cam), cam, far, 0.0);
    // Specular anti-aliasing (after Kaplanyan et al.'s screen-space normal filtering): the slopes
    // the kept waves still vary by across one pixel, from their screen derivatives, are slopes
    // one sample cannot show either; they join the lost variance. Bounded, because a quad that
    // straddles a crest's silhouette differences two unrelated surfaces. Not in the far band,
    // whose samples show that variation themselves.
    vec2 dsx = dFdx(s.slope), dsy = dFdy(s.slope);
#ifdef TRUTH
    float pixelVar = 0.0;
#else
    float pixelVar = far ? 0.0 : min(PIXEL_VAR_SCALE * (dot(dsx, dsx) + dot(dsy, dsy)), 0.1);
#endif
    vec3 col = shadeSample(s, pixelVar);
    float reach = length(s.p.xz - ro.xz);
    for (int k = 1; k < samples; k++) {
        vec3 rd = viewRay(fragCoord + vec2(0.0, (float(k) + 0.5) * step - 0.5), cam);
        Sample sk = traceSample(ro, rd, cam, far, reach);
        reach = length(sk.p.xz - ro.xz);
        col += shadeSample(sk, 0.0);
    }
    col /= float(samples);
    fragColor = vec4(pow(col, vec3(1.0 / 2.2)) + ditherNoise(fragCoord), 1.0);
}
