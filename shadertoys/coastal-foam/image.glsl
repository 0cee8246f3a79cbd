// coastal-foam — ridge-noise waves running onto a rocky shore, with foam where the water
// meets the rock and on the breaking crests. #define LAKE for a calm FBM lake instead.
//
// Technique and parameters (the why):
//   * Two height fields, both ray-marched: the rock h_r (a shore ramp from -5 m out at sea to
//     +2.5 m inland, plus ridged FBM relief (1 - |2n - 1|)^2 for sharp crests and gullies, plus
//     boulders in the surf zone) and the water h_w. The nearer hit wins.
//   * Sea: a swell of wavelength ~9 m (k = 0.7 rad/m, deep-water w = sqrt(g k) = 2.6 rad/s)
//     shaped as a ridge, s = 1 - |sin(theta/2)|: the cusp gives the sharp crest and broad trough
//     of real waves; the crest lines are bent by low-frequency noise. Octaves of ridge noise
//     (1 - |2 n - 1|) add chop: 2 while marching, 5 for the normal (cheap march, fine detail).
//     The swell grows as the water shoals (amplitude x2.2 toward the shore) and dies where it
//     breaks on the rock. Rock terraces (0.45 m steps, 55 %) give the ledges of bedded rock.
//   * Two more swell trains (6.5 m from 18 deg left, 12 m from 25 deg right) and a crest envelope
//     on each make crests a few wavelengths long instead of endless regular lines; in the surf
//     zone the main crest peaks into a breaker (a lip ~ r^10) with a whitewater mound behind it.
//   * Rock silhouettes: a ray that just misses the rock takes its colour by the share of the
//     pixel the rock covers (closest clearance against the pixel's angle); off under TRUTH.
//   * Foam: (1) contact foam where the water thickness h_w - h_r is near zero, i.e. where the
//     surface meets the rock, widened when a crest arrives (wash); (2) crest foam where the
//     ridge s is near 1 inside the surf zone, on the spilling front face and in a decaying trail
//     behind each crest. A foam density is turned into coverage against an advected texture
//     (FBM punched with random-size round holes, like bursting bubbles): dense foam is solid,
//     thin foam breaks into lace.
//   * Water colour: vertical water thickness over the rock gives a Beer-law mix from the
//     rock's colour (submerged ledges) to deep sea green-blue; thin crests get a back-lit
//     sub-surface tint; sky reflection by Schlick Fresnel (F0 = 0.02) plus a sun glitter lobe.
//   * Filtering by pixel footprint (distance x pixel angle / grazing sine): chop octaves finer
//     than about two pixels fade out of the normal, the sun lobe widens (normalised), the
//     foam's bubble holes average out and the foam edge widens, so far foam and glitter do not
//     alias. The sea's reflection is shaded at four points of the pixel's footprint on the
//     water (the chop's normal at each, the swell's once) and averaged by the area each facet
//     shows the eye; the foam's lace at two points up the screen. Rock: a soft sun shadow
//     (height-field march) and crevice occlusion give real blacks.
//   * Aerial perspective with per-channel extinction (blue scatters most) into the horizon haze.
//   * LAKE: the water becomes slow value-noise FBM (+-4 cm) with fine cat's-paw ripples in the
//     normal, darker and greener, with only a thin contact line of foam and no breaking crests.
//   * TRUTH (`toyhost run --define TRUTH`): the scene itself, for ../shared/tools/gallery_truth.py
//     to average: zero footprint (every chop octave, the narrow sun lobe, the foam's holes and
//     sharp edge, one point per sample, all cloud octaves in the reflection), no distance
//     flattening of the sea, and 2 x 2 samples in each truth pixel, so the tool's 16 become 64
//     (16 do not converge on the far sun sparkles; see PIXEL_SAMPLES). The aerial perspective
//     stays (the scene's air).
//   iMouse: drag horizontally to turn the camera.

// #define LAKE

const vec3 SUN_DIR = vec3(-0.86, 0.50, 0.10);     // afternoon sun over the sea, ahead-left, out of frame
const vec3 SUN_COL = vec3(1.45, 1.25, 1.00);
const float WMAX = 1.2;                           // water surface bounds, m
const float WMIN = -0.8;
const float RMAX = 4.5;                           // rock never higher than this, m
const float CHOP_SLOPE_VAR = 0.008;               // the chop's slope variance per axis that the filter loses at most (fit to the truth)
// march steps: the truth takes more water steps (its samples are the best picture the port can
// make). The rock march ends where it converges: a ray grazing the coast 100 m out takes up to
// ~160 steps, and a bound of 80 left those far rocks out of the picture (the water behind them
// showed instead); most rays take ~10.
#ifdef TRUTH
const int WATER_STEPS = 64;
// samples per truth pixel, a PIXEL_SAMPLES x PIXEL_SAMPLES grid: the tool's 16 samples a port pixel
// do not converge on this sea's sun sparkles (two 16-sample truths on grids 1/8 pixel apart differ
// by 28.7 dB in the far band), 64 do (37.5 dB against 256)
const int PIXEL_SAMPLES = 2;
#else
const int WATER_STEPS = 48;
#endif
const int ROCK_STEPS = 256;
const float LOST_HALF = 0.1;                      // footprint (m) at which half of it is filtered
const float STACK_STRIP = 0.35;                   // a pixel's strip of water (m) above which it takes two samples

// ----------------------------------------------------------------------------- noise --
float hash21(vec2 p) {
    uvec2 u = uvec2(ivec2(floor(p)) + 32768);
    uint h = (u.x * 0x45d9f3bu) ^ (u.y * 0x119de1f3u + 0x632be5abu);
    h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
    return float(h) * (1.0 / 4294967296.0);
}

float vnoise(vec2 p) {                              // 0 .. 1
    vec2 i = floor(p), f = p - i;
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash21(i), hash21(i + vec2(1, 0)), u.x),
               mix(hash21(i + vec2(0, 1)), hash21(i + vec2(1, 1)), u.x), u.y);
}

const mat2 ROT = mat2(1.6, 1.2, -1.2, 1.6);        // rotate + scale x2 between octaves

float ridgedFbm(vec2 p, int oct) {                  // 0 .. 1, sharp ridges
    float s = 0.0, a = 0.5, w = 0.0;
    for (int i = 0; i < 6; i++) {
        if (i >= oct) break;
        float r = 1.0 - abs(2.0 * vnoise(p) - 1.0);
        s += a * r * r;
        w += a;
        p = ROT * p + 3.7;
        a *= 0.5;
    }
    return s / w;
}

float fbm(vec2 p, int oct) {                        // 0 .. 1
    float s = 0.0, a = 0.5, w = 0.0;
    for (int i = 0; i < 6; i++) {
        if (i >= oct) break;
        s += a * vnoise(p);
        w += a;
        p = ROT * p + 1.3;
        a *= 0.5;
    }
    return s / w;
}

// ------------------------------------------------------------------------------ rock --
float shoreX(float z) { return 5.0 + 2.5 * sin(z * 0.12 + 1.0) + 1.2 * sin(z * 0.31 + 0.4); }

// signed distance across the shore (m): < 0 at sea, > 0 on land (cheap, analytic)
float shoreS(vec2 p) { return p.x - shoreX(p.y); }

float boulderMask(vec2 p, float s) {
    float b = vnoise(p * 0.28 + vec2(5.2, 1.7));
    float m = smoothstep(0.56, 0.86, b);
    return m * smoothstep(-16.0, -7.0, s) * (1.0 - smoothstep(-3.0, 1.0, s));
}

float rockH(vec2 p, int oct) {
    float s = shoreS(p);
    float base = -5.0 + 6.8 * smoothstep(-14.0, 9.0, s);
    float land = smoothstep(-7.0, 1.0, s);
    float bm = boulderMask(p, s);
    float broad = (fbm(p * 0.09, 2) - 0.5) * 2.6 * land;            // big rock masses
    float relief = (ridgedFbm(p * 0.30, oct) - 0.45) * 1.5 * max(land, bm);
    float h = base + broad + relief + 2.4 * sqrt(bm);
    // sedimentary ledges: pull the height toward 0.45 m steps (continuous terrace)
    float k = h / 0.45;
    float terr = (floor(k) + smoothstep(0.55, 0.95, fract(k))) * 0.45;
    return mix(h, terr, 0.55 * max(land, bm));
}

vec3 rockNormal(vec2 p) {
    const float e = 0.03;
    float h = rockH(p, 6);
    vec3 n = normalize(vec3(h - rockH(p + vec2(e, 0.0), 6), e, h - rockH(p + vec2(0.0, e), 6)));
    // granular bump (shading only): gradient of a fine ridged noise
    vec2 q = p * 9.0;
    float b0 = ridgedFbm(q, 2);
    vec2 g = vec2(ridgedFbm(q + vec2(0.15, 0.0), 2) - b0, ridgedFbm(q + vec2(0.0, 0.15), 2) - b0) / 0.15;
    return normalize(n - 0.06 * vec3(g.x, 0.0, g.y));
}

// ----------------------------------------------------------------------------- water --
#ifdef LAKE
float waterHf(vec2 p, float t, int oct, float footprint) {
    // calm lake: slow drifting value-noise FBM, 4 cm amplitude
    float h = 0.08 * (fbm(p * 0.45 + vec2(0.05, 0.03) * t, oct) - 0.5)
            + 0.02 * (vnoise(p * 2.1 - vec2(0.2, 0.1) * t) - 0.5);
    float keep = 1.0 - smoothstep(0.25, 0.6, 7.0 * footprint);   // ripples finer than a pixel fade out
    if (oct > 3) h += 0.006 * keep * (fbm(p * 7.0 + vec2(0.6, -0.4) * t, 2) - 0.5);   // cat's-paw ripples (normals only)
    return h;
}
// the normal's two parts: waterHf at 5 octaves = waterSwell + waterChop
float waterSwell(vec2 p, float t, float footprint) { return waterHf(p, t, 5, 1.0); }   // ripples faded out
float waterChop(vec2 p, float t, int oct, float footprint) {
    float keep = 1.0 - smoothstep(0.25, 0.6, 7.0 * footprint);
    return oct > 3 ? 0.006 * keep * (fbm(p * 7.0 + vec2(0.6, -0.4) * t, 2) - 0.5) : 0.0;
}
float swellRidge(vec2 p, float t) { return 0.0; }
#else
float swellTheta(vec2 p, float t) {
    // crest lines roughly along z, bent by low-frequency noise; travelling toward +x (shore)
    float warp = 2.5 * sin(0.09 * p.y) + 5.0 * vnoise(p * vec2(0.02, 0.05));
    return 0.70 * (p.x + warp) - 2.62 * t;
}
float swellRidge(vec2 p, float t) {                // 1 on a crest, 0 in the trough
    return 1.0 - abs(sin(0.5 * swellTheta(p, t)));
}
// a 0..1 envelope along a crest: two incommensurate sines (cheap: it runs in every march step)
float envelope1(float u) {
    return smoothstep(-0.3, 0.9, sin(u) * sin(0.37 * u + 1.9));
}
// Crests of real swell are a few wavelengths long, not endless lines: the main train's height
// comes and goes along each crest (0.3 .. 1), drifting slowly.
float crestEnvelope(vec2 p, float t) {
    return 0.3 + 0.7 * envelope1(0.16 * p.y + 0.05 * p.x - 0.05 * t + 0.6 * sin(0.013 * p.x));
}
// Two more swell trains with their own directions (spread about the main one), wavelengths and
// crest lengths, so no single regular swell stripes the far field: 6.5 m from 18 deg left and
// 12 m from 25 deg right, each at its deep-water speed sqrt(g k). `footprint` fades a train whose
// crests come closer than about a pixel (0 = exact).
float swellOthers(vec2 p, float t, float footprint) {
    const vec2 D2 = vec2(0.951, 0.309);
    const vec2 D3 = vec2(0.906, -0.423);
    float th2 = 0.97 * dot(p, D2) - 3.08 * t + 1.5 * sin(0.05 * p.y + 0.02 * p.x);
    float th3 = 0.52 * dot(p, D3) - 2.26 * t + 2.0;
    float r2 = 1.0 - abs(sin(0.5 * th2));
    float r3 = 1.0 - abs(sin(0.5 * th3));
    float e2 = envelope1(0.21 * dot(p, vec2(-D2.y, D2.x)) + 0.03 * dot(p, D2) + 0.3 + 0.06 * t);
    float e3 = envelope1(0.12 * dot(p, vec2(-D3.y, D3.x)) + 0.02 * dot(p, D3) + 4.1 - 0.04 * t);
    float k2 = 1.0 - smoothstep(0.6, 1.6, 0.97 * footprint);
    float k3 = 1.0 - smoothstep(0.6, 1.6, 0.52 * footprint);
    return 0.40 * e2 * k2 * (r2 * r2 - 0.4) + 0.55 * e3 * k3 * (r3 * r3 - 0.4);
}
// `footprint`: the width of water a pixel covers (0 = exact); chop octaves whose noise cells
// come closer than about two pixels fade out (unfiltered they glitter and shimmer far away).
// the swell trains and breakers (`others`: with the two low trains)
float waterSwellO(vec2 p, float t, bool others, float footprint) {
    float s = shoreS(p);
    float shoal = 1.0 + 1.2 * smoothstep(-22.0, -5.0, s);          // waves grow in shallows
    float die = 1.0 - 0.75 * smoothstep(-3.0, 1.5, s);             // ... and collapse at the rock
    float A = 0.24 * shoal * die * (0.6 + 0.8 * vnoise(vec2(p.y * 0.07, 0.5)));
    float theta = swellTheta(p, t);
    float r = 1.0 - abs(sin(0.5 * theta));
    float env = crestEnvelope(p, t);
    float h = A * (env * (r * r * r - 0.25) + (others ? swellOthers(p, t, footprint) : 0.0));
    // breakers: in the surf zone the main crest peaks into a steep lip and a mound of whitewater
    // trails behind it (both where the crest is long enough to break)
    float surfB = smoothstep(-15.0, -7.0, s) * (1.0 - smoothstep(-3.0, 0.5, s));
    float behind = fract(-theta / 6.28318530718);
    h += A * surfB * env * env * (1.1 * pow(r, 10.0) + 0.35 * exp(-6.0 * behind));
    return h;
}
float waterSwell(vec2 p, float t, float footprint) { return waterSwellO(p, t, true, footprint); }
// ridge-noise chop, advected in the wave direction
float waterChop(vec2 p, float t, int oct, float footprint) {
    float h = 0.0;
    float amp = 0.085;
    vec2 q = p * 0.6;
    float freq = 0.6;
    for (int i = 0; i < 5; i++) {
        if (i >= oct || freq * footprint >= 1.0) break;    // the rest is faded out: skip it
        float n = 1.0 - abs(2.0 * vnoise(q + vec2(1.2, 0.3) * t * (1.0 + 0.5 * float(i))) - 1.0);
        h += amp * (n * n - 0.45) * (1.0 - smoothstep(0.4, 1.0, freq * footprint));
        q = ROT * q + 2.1;
        amp *= 0.45;
        freq *= 2.0;
    }
    return h;
}
// the other trains are low (<= 0.3 m): the march (2 octaves) leaves them to the normal
float waterHf(vec2 p, float t, int oct, float footprint) {
    return waterSwellO(p, t, oct > 2, footprint) + waterChop(p, t, oct, footprint);
}
#endif
float waterH(vec2 p, float t, int oct) { return waterHf(p, t, oct, 0.0); }

// ----------------------------------------------------------------------------- march --
// rock: from t0 to t1 (both along the ray), returns t or -1. On a miss, `edge` is the share of
// the pixel the rock's silhouette covers (x) and where along the ray it passed closest (y): the
// ray's clearance over the rock as an angle, against the pixel's angle (a straight edge across a
// box pixel covers 0.5 - clearance / pixel). Only rock above the mean water (0.2 m) counts.
// Both marches refine a crossing by bisection in the same loop (5 halvings of the last step for
// the rock, 4 for the water), not in a loop of their own nested in the step loop: llvmpipe runs
// an if's body for every pixel and a loop's at least once, so a nested bisection cost one more
// height-field evaluation at every step (docs/performance.md: 257 -> 203 ms a frame).
float marchRock(vec3 ro, vec3 rd, float t0, float t1, float sy, out vec2 edge) {
    float t = t0, tp = t0;
    float pix = sy * 2.0 / (1.6 * iResolution.y);       // the sample's height as an angle
    float best = 0.5 * pix;
    edge = vec2(0.0, -1.0);
    int steps = 0, halvings = -1;       // halvings >= 0: bisecting [tp, t]
    for (int i = 0; i < ROCK_STEPS + 5; i++) {
        if (halvings < 0 && (t > t1 || steps == ROCK_STEPS)) break;
        float m = halvings < 0 ? t : 0.5 * (tp + t);
        vec3 p = ro + rd * m;
        float hr = rockH(p.xz, 4);
        float d = p.y - hr;
        if (halvings >= 0) {
            if (d < 0.0) t = m; else tp = m;
            if (++halvings == 5) return 0.5 * (tp + t);
            continue;
        }
#ifndef TRUTH
        if (d < best * t && d > 0.0 && hr > 0.2) { best = d / t; edge.y = t; }
#endif
        if (d < 0.0) { halvings = 0; continue; }
        tp = t;
        // out at sea (shoreS < -16) the rock lies at -5 m, under any water: step to where the
        // shore zone may begin (shoreS changes by at most 1.25 m per metre across the ground)
        float sea = (-16.0 - shoreS(p.xz)) / 1.25;
        t += max(max(0.02 + 0.004 * t, 0.45 * d), sea / max(length(rd.xz), 1e-3));
        steps++;
    }
    if (edge.y > 0.0) edge.x = 0.5 - best / pix;
    return -1.0;
}

float marchWater(vec3 ro, vec3 rd, float t0, float t1, float time) {
    float t = t0, tp = t0;
    int steps = 0, halvings = -1;       // halvings >= 0: bisecting [tp, t]
    for (int i = 0; i < WATER_STEPS + 4; i++) {
        if (halvings < 0 && (t > t1 || steps == WATER_STEPS)) break;
        float m = halvings < 0 ? t : 0.5 * (tp + t);
        vec3 p = ro + rd * m;
        float d = p.y - waterH(p.xz, time, 2);
        if (halvings >= 0) {
            if (d < 0.0) t = m; else tp = m;
            if (++halvings == 4) return 0.5 * (tp + t);
            continue;
        }
        if (d < 0.0) { halvings = 0; continue; }
        tp = t;
        t += max(0.03 + 0.005 * t, 0.6 * d / max(-rd.y, 0.05));
        steps++;
    }
    return t1;   // near the horizon: take the lower bound plane
}

// ------------------------------------------------------------------------------- sky --
// `clouds`: octaves of the cloud FBM (5; 2 in the water's reflection, which blurs the rest)
vec3 skyO(vec3 rd, int clouds) {
    vec3 L = normalize(SUN_DIR);
    float y = max(rd.y, 0.0);
    // a clear afternoon: the horizon pale blue, not the grey-white (0.78, 0.80, 0.82) that
    // turned the far sea milky through the aerial perspective (issue 29)
    vec3 c = mix(vec3(0.60, 0.72, 0.86), vec3(0.20, 0.40, 0.76), pow(y, 0.45));
    float sd = max(dot(rd, L), 0.0);
    c += vec3(1.0, 0.75, 0.45) * (0.35 * pow(sd, 6.0) + 0.25 * pow(sd, 48.0));
    c += vec3(1.0, 0.9, 0.7) * 25.0 * pow(sd, 1800.0);
    // thin clouds on a plane 1 km up
    if (rd.y > 0.01) {
        vec2 cp = rd.xz / rd.y * 0.9 + vec2(0.0, 0.02) * iTime;
        float cl = smoothstep(0.50, 0.85, fbm(cp, clouds)) * smoothstep(0.01, 0.12, rd.y);
        c = mix(c, vec3(1.0, 0.96, 0.92) * (0.85 + 0.4 * pow(sd, 4.0)), 0.75 * cl);
    }
    return c;
}

vec3 sky(vec3 rd) { return skyO(rd, 5); }

// Aerial perspective with per-channel extinction: the air scatters blue most, so distant rock
// and sea lose red last and take the horizon haze's colour channel by channel.
vec3 aerial(vec3 col, vec3 rd, float dist) {
    vec3 ext = exp(-vec3(0.000007, 0.00001, 0.000014) * dist * dist);   // clear air (halved, issue 29)
    return col * ext + sky(vec3(rd.x, 0.02, rd.z)) * (1.0 - ext);
}

// ----------------------------------------------------------------------------- shade --
vec3 rockAlbedo(vec2 p, float h, vec3 n) {
    vec2 q = p + vec2(h, -h) * 0.8;                              // h term: less streaking on cliffs
    float v = fbm(q * 1.7, 3);
    vec3 c = mix(vec3(0.13, 0.12, 0.11), vec3(0.52, 0.46, 0.38), smoothstep(0.25, 0.75, v));
    c *= 0.7 + 0.3 * ridgedFbm(q * 6.0, 2);                       // cracks and grain
    c = mix(c, vec3(0.62, 0.52, 0.30), 0.45 * smoothstep(0.68, 0.8, vnoise(q * 3.1)) * smoothstep(1.0, 2.0, h)); // lichen
    c = mix(c, vec3(0.52, 0.48, 0.40), smoothstep(0.75, 0.95, n.y) * smoothstep(1.2, 2.5, h) * 0.6);
    // wet dark band and green algae just above the water line
    c *= mix(0.45, 1.0, smoothstep(0.1, 1.1, h));
    c = mix(c, vec3(0.10, 0.14, 0.06), smoothstep(0.6, 0.0, h) * smoothstep(-0.6, 0.0, h) * 0.6);
    return c;
}

// Soft shadow of the rock toward the sun: march the height field (3 octaves) and keep the
// closest miss over distance (penumbra), 0 = in shadow. Rock pixels only.
float rockShadow(vec3 p, vec3 L) {
    float res = 1.0, t = 0.08;
    for (int i = 0; i < 24; i++) {
        vec3 q = p + L * t;
        if (q.y > RMAX) break;
        float h = q.y - rockH(q.xz, 3);
        res = min(res, 10.0 * h / t);
        if (res < 0.002) return 0.0;
        t += clamp(0.6 * h, 0.06, 0.8);
    }
    return clamp(res, 0.0, 1.0);
}

// `wet` 0..1: a water film fills the rock's pores, so less light scatters back out of it: darker
// and more saturated (the albedo roughly squared), with a glossy film on top (see mainImage).
vec3 shadeRock(vec3 p, vec3 rd, vec3 n, float wet, bool shadowed) {
    vec3 L = normalize(SUN_DIR);
    vec3 alb = rockAlbedo(p.xz, p.y, n);
    alb = mix(alb, alb * alb, wet);
    float dif = max(dot(n, L), 0.0);
    if (dif > 0.0 && shadowed) dif *= rockShadow(p + n * 0.03, L);
    // crevice occlusion: the fine ridged detail is low in gullies, where little sky reaches
    float ridge = ridgedFbm(p.xz * 0.88, 2);
    float ao = clamp(1.4 * ridge * ridge, 0.0, 1.0);     // deep cracks see almost no sky
    vec3 amb = vec3(0.32, 0.40, 0.52) * (0.55 + 0.45 * n.y) * ao;
    return alb * (SUN_COL * dif * (0.6 + 0.4 * ao) + amb);
}

// Rock with the swash's water film: wet rock just above the water (the swash keeps it wet) is
// darker and more saturated, under a glossy film: Schlick's Fresnel (F0 = 0.02) of the sky, kept
// under 0.1 because the film follows the rock's roughness (no mirror-bright grazing streaks, which
// read as foam), and small sun glints where the film faces the sun. `hw`: the water height there.
vec3 shadeWetRock(vec3 p, vec3 rd, float hw, bool shadowed) {
    float film = smoothstep(0.6, 0.0, p.y - hw);
    vec3 nr = rockNormal(p.xz);
    vec3 col = shadeRock(p, rd, nr, film, shadowed);
    vec3 rr = reflect(rd, nr);
    float sheen = min(0.02 + 0.98 * pow(1.0 - clamp(dot(-rd, nr), 0.0, 1.0), 5.0), 0.1);
    float glint = pow(max(dot(rr, normalize(SUN_DIR)), 0.0), 80.0) * (80.0 + 2.0) / 6.2832;
    col += film * (sky(rr) * sheen + SUN_COL * glint * 0.05);
    return col;
}

// distance to the nearest jittered feature point, and that point's random value
vec2 cellNear(vec2 p) {
    vec2 i = floor(p), f = p - i;
    float d1 = 9.0, id = 0.0;
    for (int y = -1; y <= 1; y++)
    for (int x = -1; x <= 1; x++) {
        vec2 c = vec2(x, y);
        vec2 o = vec2(hash21(i + c), hash21(i + c + 71.3));
        float d = length(c + o - f);
        if (d < d1) { d1 = d; id = hash21(i + c + 13.7); }
    }
    return vec2(d1, id);
}

// foam texture 0..1, advected with the water: a soft FBM body punched with round holes of
// random size (the bursting bubbles that give sea foam its lace)
float foamTex(vec2 p, float t, float footprint) {
    vec2 q = p * 1.4 + vec2(0.6 * t, 0.1 * t);
    float body = fbm(q, 3);
    vec2 w = q * 3.2 + 0.8 * vec2(vnoise(q * 1.3), vnoise(q * 1.3 + 9.1));
    vec2 c1 = cellNear(w);
    vec2 c2 = cellNear(w * 2.3 + 5.0);
    float holes = smoothstep(0.15 + 0.45 * c1.y, 0.3 + 0.5 * c1.y, c1.x)
                * smoothstep(0.1 + 0.35 * c2.y, 0.25 + 0.4 * c2.y, c2.x);
    // holes finer than a pixel or two average to their coverage (0.35, fit against the 16-sample
    // truth; 0.55 turned the far foam into a white sheet) instead of aliasing
    holes = mix(holes, 0.35, smoothstep(0.03, 0.12, footprint));
    return body * (0.55 + 0.45 * holes) + 0.1;
}

// foam coverage for a foam density 0..1: dense foam is solid, thin foam breaks into lace
// `footprint` widens the edge a little (anti-aliased lace); up to 0.4 wider (before issue 29)
// spread far foam over water the truth shows clear.
float foamCover(float density, float tex, float footprint) {
    float thr = 1.0 - density;
    float w = 0.12 + min(1.0 * footprint, 0.1);
    return smoothstep(thr - w, thr + w, tex) * smoothstep(0.0, 0.15, density);
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

// Slope variance (per axis) the water's normal loses at `footprint` (the chop octaves faded and
// the normal's box filter): it grows with the footprint up to the chop's whole variance.
float lostSlopeVariance(float footprint) {
#ifdef TRUTH
    return 0.0;
#else
    return CHOP_SLOPE_VAR * footprint / (footprint + LOST_HALF);
#endif
}

// The sea's surface light (sky reflection, water body, sun glitter) averaged over the pixel:
// the normal at four points of its footprint on the water (a rotated grid, offsets in pixels
// along dpx, dpy: one pixel to the right / up), each shaded through four normals spread by the
// slope variance its own footprint no longer shows, and all weighted by the area they show the
// eye. A single normal left the near chop's sky reflection a 1-sample pattern the truth averages
// (28.8 -> 30.3 dB). The swell is smooth over a pixel: its slope is taken once, the chop's at
// each point. The truth (footprint 0) takes one point. `n`: the mean normal.
vec3 seaSurface(vec3 p, vec3 rd, vec2 dpx, vec2 dpy, float footprint, float fade, vec3 body,
                float t, out vec3 n) {
    vec3 L = normalize(SUN_DIR);
#ifdef TRUTH
    const int POINTS = 1;
    const int CLOUDS = 5;
    const float GLINT = 1.2;        // the sun's glitter, in SUN_COL
#else
    const int POINTS = 4;
    const int CLOUDS = 2;
    // the widened lobe at four points carries more light than the truth's average of the narrow
    // one: 0.9 where the scene has 1.2 (fit against the converged truth: 31.8 -> 32.4 dB; with
    // 1.2 the water below the far band was 0.4-1.4 levels too bright on average, now within 0.2;
    // 0.7-1.0 are within 0.15 dB)
    const float GLINT = 0.9;
#endif
    // each point's share of the footprint: 0.4, the shares overlap (fit against the converged
    // truth: a quarter, which would tile it, left the far band 0.2 dB lower and too detailed, 1.09)
    float fp = 0.4 * footprint;
    float e = max(0.02, fp);
    float unseen = lostSlopeVariance(fp);
    vec2 along = normalize(rd.xz + vec2(1e-6, 0.0));
    vec2 across = vec2(-along.y, along.x);
    // sun glitter: a normalised lobe that widens where the footprint filtered slopes away
    float sp = 300.0 / (1.0 + 300.0 * 0.02 * smoothstep(0.0, 1.0, fp * 16.0));
    float hs = waterSwell(p.xz, t, e);
    vec2 swellD = vec2(hs - waterSwell(p.xz + vec2(e, 0.0), t, e), hs - waterSwell(p.xz + vec2(0.0, e), t, e));
    vec3 acc = vec3(0.0);
    float wsum = 0.0;
    n = vec3(0.0);
    for (int k = 0; k < POINTS; k++) {
        vec2 o = POINTS == 1 ? vec2(0.0) : vec2(k == 0 ? 0.125 : k == 1 ? 0.375 : k == 2 ? -0.125 : -0.375,
                                               k == 0 ? 0.375 : k == 1 ? -0.125 : k == 2 ? -0.375 : 0.125);
        vec2 q = p.xz + o.x * dpx + o.y * dpy;
        float hc = waterChop(q, t, 5, e);
        vec3 nq = normalize(vec3(swellD.x + hc - waterChop(q + vec2(e, 0.0), t, 5, e), e,
                                 swellD.y + hc - waterChop(q + vec2(0.0, e), t, 5, e)));
        nq = normalize(mix(vec3(0.0, 1.0, 0.0), nq, 0.35 + 0.65 * fade));
        n += nq;
        // Fresnel x sky over the slopes the filtered normal no longer shows (the chop octaves
        // and the box filter took them): four normals spread by that variance, each weighted by
        // the area it shows the eye. A flattened normal alone turns the far sea into a grazing
        // mirror, brighter than the water it stands for (the milky haze).
        vec2 slope = -nq.xz / nq.y;
        float F = 0.0, area = 0.0;
        vec3 refl = vec3(0.0);
        for (int j = 0; j < 4; j++) {
            vec2 oj = vec2(j & 1, j >> 1) * 2.0 - 1.0;
            vec2 sj = slope + sqrt(unseen) * (oj.x * along + oj.y * across);
            vec3 nj = normalize(vec3(-sj.x, 1.0, -sj.y));
            float cosj = clamp(dot(-rd, nj), 0.0, 1.0);
            float seen = cosj / nj.y;
            float Fj = 0.02 + 0.98 * pow(1.0 - cosj, 5.0);
            vec3 rj = reflect(rd, nj);
            rj.y = abs(rj.y);
            refl += seen * Fj * skyO(rj, CLOUDS);
            F += seen * Fj;
            area += seen;
        }
        vec3 rf = reflect(rd, nq);
        rf.y = abs(rf.y);
        float glint = pow(max(dot(rf, L), 0.0), sp) * (sp + 2.0) / 302.0;
        acc += body * (area - F) + refl + area * SUN_COL * GLINT * glint;
        wsum += area;
    }
    n = normalize(n);
    return acc / max(wsum, 1e-6);
}

// The camera: standing on the rocks, looking out to sea along the coast (focal length 1.6).
void camera(out vec3 ro, out vec3 fw, out vec3 rt, out vec3 up) {
    float yaw = 0.0;
    if (iMouse.z > 0.0) yaw = (iMouse.x / iResolution.x - 0.5) * 1.5;
    ro = vec3(7.0, 4.2, -7.5);
    vec3 fw0 = vec3(-14.0, -3.6, 13.0);
    fw0.xz = mat2(cos(yaw), sin(yaw), -sin(yaw), cos(yaw)) * fw0.xz;
    fw = normalize(fw0);
    rt = normalize(cross(vec3(0.0, 1.0, 0.0), fw));
    up = cross(fw, rt);
}

// One sample of the picture at `fragCoord` (a point in pixels), tone-mapped (linear, before the
// display gamma). `sy`: the sample's height as a share of the pixel's (1, or 1/2 for each of two
// samples stacked up it): the footprint its filters take. `starts`: where along the ray the water
// and the rock march may start (0: from the top); on return, where a sample just above this one
// may start: a ray above another from the same eye meets a height field no nearer than it does.
vec3 pictureSample(vec2 fragCoord, float sy, inout vec2 starts) {
    float t = iTime;
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro, fw, rt, up;
    camera(ro, fw, rt, up);
    vec3 rd = normalize(uv.x * rt + uv.y * up + 1.6 * fw);

    vec3 L = normalize(SUN_DIR);
    vec3 col;
    const float FAR = 400.0;

    // water: only between the planes y = WMAX and y = WMIN
    float tw = FAR;
    if (rd.y < 0.0) {
        float tw0 = max((ro.y - WMAX) / -rd.y, 0.0);
        float tw1 = min((ro.y - WMIN) / -rd.y, FAR);
        if (tw0 < FAR) tw = marchWater(ro, rd, max(tw0, starts.x), tw1, t);
        starts.x = tw < tw1 ? 0.98 * tw : 0.0;     // a hit, not the march giving up
    }
    // rock: from where the ray drops below RMAX to the water hit
    float tr = -1.0;
    vec2 edge = vec2(0.0);
    {
        float tr0 = rd.y < 0.0 ? max((ro.y - RMAX) / -rd.y, 0.0) : 0.0;
        // ... and an upward ray is over every rock once it passes RMAX (the sky's rays marched
        // on to 120 m: 16-38 steps of rock noise a pixel for nothing, ~12% of the frame)
        float tr1 = rd.y > 0.0 ? (RMAX - ro.y) / rd.y : 120.0;
        float trEnd = min(min(tw, 120.0), tr1);
        if (ro.y < RMAX || rd.y < 0.0) tr = marchRock(ro, rd, max(tr0, starts.y), trEnd, sy, edge);
        starts.y = 0.98 * (tr > 0.0 ? tr : trEnd);
    }

    // The rock, shaded once: where the ray met it, or at the silhouette it just missed (that one
    // takes its share of the pixel below; a silhouette faces the sun or the eye, so its shadow march
    // is skipped: it cost 45 ms a frame). One call site: llvmpipe runs an if's body for every
    // pixel, and a second copy of the rock's shading for the silhouettes cost ~8% of the frame.
    vec3 rockCol = vec3(0.0);
    if (tr > 0.0 || edge.x > 0.0) {
        float tq = tr > 0.0 ? tr : edge.y;
        vec3 p = ro + rd * tq;
        if (tr < 0.0) p.y = rockH(p.xz, 4);
        float hw = waterH(p.xz, t, 3);
        rockCol = aerial(shadeWetRock(p, rd, hw, tr > 0.0), rd, tq);
    }
    if (tr > 0.0) {
        col = rockCol;
    } else if (tw < FAR && rd.y < 0.0) {
        vec3 p = ro + rd * tw;
        // the width of water one pixel covers: pixel angle x distance / grazing sine is the
        // strip's length along the view; across it the pixel resolves waves 1/sine finer, so a
        // fade by the length alone erased what the truth shows (fit: a quarter of the length,
        // 26.2 -> 28.8 dB against the 16-sample truth)
#ifdef TRUTH
        float footprint = 0.0;
        float fade = 1.0;
#else
        float footprint = sy * 0.25 * tw * 2.0 / (1.6 * iResolution.y) / max(-rd.y, 0.05);
        float fade = exp(-0.004 * tw);                   // far away the sea goes flat
#endif
        float hr = rockH(p.xz, 3);
        float depth = max(p.y - hr, 0.0);                // water thickness over the rock

        // water body: Beer-law mix from the submerged rock to the deep colour
#ifdef LAKE
        const vec3 KW = vec3(0.55, 0.35, 0.45);
        vec3 deepCol = vec3(0.015, 0.035, 0.035);
#else
        const vec3 KW = vec3(0.45, 0.12, 0.10);
        vec3 deepCol = vec3(0.012, 0.06, 0.08);
#endif
        vec3 bed = rockAlbedo(p.xz, hr, vec3(0.0, 1.0, 0.0)) * (SUN_COL * L.y + 0.3);
        vec3 trans = exp(-KW * depth * 2.2);
        vec3 body = mix(deepCol, bed, trans);
#ifndef LAKE
        // light through thin, back-lit crests
        float crest = swellRidge(p.xz, t);
        float sss = pow(max(dot(rd, L), 0.0), 2.0) * crest * crest * crest * smoothstep(-24.0, -6.0, shoreS(p.xz));
        body += vec3(0.05, 0.22, 0.20) * sss * fade;
#endif
        // the sample's footprint on a level sea (one pixel to the right, its height up; the ray's
        // derivatives on the plane y = p.y)
        vec3 rdx = normalize((uv.x + 2.0 / iResolution.y) * rt + uv.y * up + 1.6 * fw) - rd;
        vec3 rdy = normalize(uv.x * rt + (uv.y + sy * 2.0 / iResolution.y) * up + 1.6 * fw) - rd;
        float gy = max(-rd.y, 0.01);
        vec2 dpx = tw * (rdx.xz + rd.xz * rdx.y / gy);
        vec2 dpy = tw * (rdy.xz + rd.xz * rdy.y / gy);
        vec3 n;
        col = seaSurface(p, rd, dpx, dpy, footprint, fade, body, t, n);

        // ----- foam
        float s = shoreS(p.xz);
#ifdef LAKE
        float density = 0.8 * smoothstep(0.08, 0.0, depth);
#else
        float r = swellRidge(p.xz, t);
        // (1) contact foam where the water thickness over the rock goes to zero; a passing
        //     crest throws it further out (wash)
        float reach = 0.5 + 1.1 * r * r;
        float contact = smoothstep(reach, 0.0, depth) + 0.6 * smoothstep(2.6, 0.3, depth);
        // (2) crest foam inside the surf zone, with a fading trail behind each crest
        float theta = swellTheta(p.xz, t);
        float behind = fract(-theta / 6.28318530718);           // 0 at the crest, grows behind it
        float surf = smoothstep(-18.0, -7.0, s);
        float ahead = 1.0 - behind;                              // 0 at the crest, grows ahead
        float crestF = surf * (smoothstep(0.78, 0.97, r)
                     + 0.8 * exp(-5.0 * behind) * smoothstep(-15.0, -6.0, s)     // trail
                     + 0.7 * exp(-14.0 * ahead) * smoothstep(-11.0, -4.0, s));   // spilling face
        crestF *= 0.3 + 0.7 * smoothstep(0.3, 0.8, vnoise(p.xz * vec2(0.35, 0.12) + 3.0));  // breaks in patches
        crestF *= smoothstep(0.35, 0.8, crestEnvelope(p.xz, t));                           // where the crest is long
        float density = clamp(contact + crestF, 0.0, 0.93);
#endif
        // The lace at two points a half pixel apart up the screen (the pixel's long axis on the
        // water), its coverage averaged: one point left the lace a 1-sample pattern (+0.4 dB).
        // Open water has no foam: a GPU skips the texture there. llvmpipe runs an if's body for
        // every pixel, so there this test saves nothing (248 ms a frame with it, 247 without).
        if (density > 0.0) {
            // thick foam is brighter; thin foam lets a little of the water through
            vec3 foamCol = vec3(0.92, 0.95, 0.96) * (SUN_COL * (0.35 + 0.65 * max(dot(n, L), 0.0)) * 0.75 + vec3(0.30, 0.36, 0.44));
#ifdef TRUTH
            const int FOAM_POINTS = 1;
#else
            const int FOAM_POINTS = 2;
#endif
            vec3 paint = vec3(0.0);
            float cover = 0.0;
            for (int k = 0; k < FOAM_POINTS; k++) {
                float o = FOAM_POINTS == 1 ? 0.0 : (k == 0 ? 0.25 : -0.25);
                float ft = foamTex(p.xz + o * dpy, t, footprint);
                float foam = foamCover(density, ft, footprint);
                foam *= fade;
                paint += foamCol * (0.82 + 0.25 * ft) * foam;
                cover += foam;
            }
            col = col * (1.0 - cover / float(FOAM_POINTS)) + paint / float(FOAM_POINTS);
        }
        col = aerial(col, rd, tw);
    } else {
        col = sky(rd);
    }

    // the rock's silhouette over the water or the sky it just missed, by the share it covers
    if (tr < 0.0 && edge.x > 0.0) col = mix(col, rockCol, edge.x);
    return 1.0 - exp(-1.1 * col);           // gentle tone map
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
#ifdef TRUTH
    vec3 col = vec3(0.0);
    for (int k = 0; k < PIXEL_SAMPLES * PIXEL_SAMPLES; k++) {
        vec2 o = (vec2(k % PIXEL_SAMPLES, k / PIXEL_SAMPLES) + 0.5) / float(PIXEL_SAMPLES) - 0.5;
        vec2 starts = vec2(0.0);
        col += pictureSample(fragCoord + o, 1.0, starts);
    }
    col /= float(PIXEL_SAMPLES * PIXEL_SAMPLES);
#else
    // Where a pixel's strip of water along the view (its angle x distance / grazing sine, on the
    // mean sea level) is longer than STACK_STRIP, it takes two samples stacked up it, each with
    // half its footprint: such a strip holds several crests, rocks' ledges and edges, and one
    // sample cannot say which of them the pixel shows (against the truth, the far band 29.1 ->
    // 31.1 dB). The upper sample's marches start where the lower one met the water and the rock.
    // The loop tests at its bottom: llvmpipe runs a loop's body once more than its count when the
    // test is at the top, and an if's body for every pixel (docs/performance.md), so this is the
    // form in which only the band's pixels pay for their second sample.
    vec3 ro, fw, rt, up;
    camera(ro, fw, rt, up);
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 rd = normalize(uv.x * rt + uv.y * up + 1.6 * fw);
    float strip = rd.y < -0.01 ? ro.y / -rd.y * (2.0 / (1.6 * iResolution.y)) / max(-rd.y, 0.05) : 0.0;
    int ns = strip > STACK_STRIP ? 2 : 1;
    vec2 starts = vec2(0.0);
    vec3 col = vec3(0.0);
    for (int k = 0; k < 2; k++) {
        float dy = ns == 1 ? 0.0 : float(k) * 0.5 - 0.25;
        col += pictureSample(fragCoord + vec2(0.0, dy), 1.0 / float(ns), starts);
        if (k + 1 >= ns) break;
    }
    col /= float(ns);
#endif
    col = pow(col, vec3(1.0 / 2.2));
    fragColor = vec4(col + ditherNoise(fragCoord), 1.0);
}
