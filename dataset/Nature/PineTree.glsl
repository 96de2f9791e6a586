/* sdfwb
name: Pine Tree
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A fir tree: four stacked cone tiers (exact frustums, each with a wavy rim made by
  fourteen small rounded lobes in angular repetition), a brown trunk and a star-shaped tip bud.
  Exact parts joined with min and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

// One tier: a cone of base radius r and height h whose bottom sits at y = y0; its rim is
// scalloped by fourteen small lobes.
float tier(vec3 p, float y0, float r, float h) {
    vec3 q = p - vec3(0.0, y0 + 0.5 * h, 0.0);
    float cone = sdFrustum(q, r, 0.0, 0.5 * h) - 0.015;
    vec2 s = sectorFold(q.xz, 14.0);
    float lobe = sdSphere(vec3(s.x - 0.9 * r, q.y + 0.44 * h, s.y), 0.1 * r);
    return smoothMin(cone, lobe, 0.05);
}

float sdf(vec3 p) {
    float trunk = sdCylinder(p - vec3(0.0, -0.78, 0.0), 0.1, 0.14);
    float tree = tier(p, -0.66, 0.62, 0.62);
    tree = min(tree, tier(p, -0.32, 0.5, 0.55));
    tree = min(tree, tier(p, 0.0, 0.38, 0.5));
    tree = min(tree, tier(p, 0.3, 0.26, 0.48));
    float bud = sdSphere(p - vec3(0.0, 0.82, 0.0), 0.05);
    return min(min(trunk, tree), bud);
}
