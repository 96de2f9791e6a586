/* sdfwb
name: Potted Flower
category: Nature
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A daisy in a flower pot, nodding in a breeze (period 3 s). The bloom faces +X, tilted
  up: a domed centre disc and twelve rounded petal plates by angular repetition. A curved stem
  with two leaf plates rises from a tapered pot with a rolled rim and soil. The stem and bloom
  sway by a shift s(y, t) along z whose slope stays below 0.2; that part is divided by 1.2.
  Unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float bloom(vec3 p) {
    // Local frame of the flower head: its axis points to +X, tipped 0.5 rad upwards.
    vec3 q = p - vec3(0.08, 0.48, 0.0);
    q.xy = rotate2(q.xy, -0.5);
    // Centre: a squashed dome facing along the axis (+x of the local frame).
    float disc = sdEllipsoid(q - vec3(0.02, 0.0, 0.0), vec3(0.07, 0.14, 0.14));
    // Petals: flat teardrops radiating in the local YZ plane.
    vec2 s = sectorFold(q.yz, 12.0);
    float petal = sdPlate(sdRoundCone2(s, vec2(0.1, 0.0), vec2(0.36, 0.0), 0.035, 0.065), q.x + 0.01, 0.018);
    return min(disc, petal);
}

float plant(vec3 p) {
    // Stem: a gentle curve made from two tapered segments.
    float stem = sdRoundCone(p, vec3(0.0, -0.4, 0.0), vec3(0.03, 0.05, 0.0), 0.035, 0.03);
    stem = min(stem, sdRoundCone(p, vec3(0.03, 0.05, 0.0), vec3(0.06, 0.45, 0.0), 0.03, 0.025));
    // Leaves: flat pointed plates angled off the stem, one on each side.
    vec3 l = p - vec3(0.01, -0.2, 0.0);
    vec3 la = l;
    la.yz = rotate2(la.yz, -0.7);
    float leafA = sdPlate(sdRoundCone2(la.yz, vec2(0.0), vec2(0.0, 0.3), 0.02, 0.06), la.x, 0.012);
    vec3 lb = l - vec3(0.0, 0.12, 0.0);
    lb.yz = rotate2(lb.yz, 0.8);
    float leafB = sdPlate(sdRoundCone2(lb.yz, vec2(0.0), vec2(0.0, 0.25), 0.02, 0.05), lb.x, 0.012);
    return min(min(stem, bloom(p)), min(leafA, leafB));
}

float sdf(vec3 p, float time) {
    // Pot: a tapered tub with a rolled rim and soil just below it.
    vec3 c = p - vec3(0.0, -0.62, 0.0);
    float tub = sdFrustum(c, 0.22, 0.3, 0.24);
    float rim = sdTorus(c - vec3(0.0, 0.22, 0.0), 0.3, 0.045);
    float soil = sdFrustum(c - vec3(0.0, 0.1, 0.0), 0.27, 0.29, 0.08);
    float cavity = sdFrustum(c - vec3(0.0, 0.2, 0.0), 0.26, 0.28, 0.1);
    float pot = min(max(tub, -cavity), rim);
    pot = min(pot, soil);

    // Sway sideways (along z), growing with the height above the soil.
    float h = clamp((p.y + 0.4) / 1.2, 0.0, 1.0);
    float shift = 0.12 * sin(6.2831853 * time / 3.0) * h * h;
    // |d shift / dy| <= 2 * 0.12 * h / 1.2 <= 0.2: divide by 1.2 to stay 1-Lipschitz.
    float flower = plant(vec3(p.x, p.y, p.z - shift)) / 1.2;
    return min(pot, flower);
}
