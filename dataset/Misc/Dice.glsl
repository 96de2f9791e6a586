/* sdfwb
name: Dice
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A six-sided die with rounded edges and spherical pips dimpled into its faces
  (opposite faces sum to seven: 1 on +X, 2 on +Y, 3 on +Z). A rounded box minus small
  spheres: the subtraction (max) makes it conservative.
  The audit measures it as exact: the pips are shallow, so the max() underestimate near their
  rims is below the audit's resolution; declared conservative because it is one in theory.
*/
#include "../lib/modelling.glsl"

// Distance to the pips of face value `n` drawn on a face whose local coordinates are uv
// (centred on the face) and whose depth coordinate is w (0 on the face plane).
float pips(vec2 uv, float w, int n) {
    const float r = 0.13;                 // pip radius, sunk so only a dimple shows
    const float o = 0.35;                 // corner offset
    float d = 1e3;
    vec3 c = vec3(uv, w - 0.06);
    if (n == 1 || n == 3 || n == 5) d = min(d, length(c) - r);
    if (n >= 2) {
        d = min(d, length(c - vec3(o, o, 0.0)) - r);
        d = min(d, length(c + vec3(o, o, 0.0)) - r);
    }
    if (n >= 4) {
        d = min(d, length(c - vec3(o, -o, 0.0)) - r);
        d = min(d, length(c + vec3(o, -o, 0.0)) - r);
    }
    if (n == 6) {
        d = min(d, length(c - vec3(o, 0.0, 0.0)) - r);
        d = min(d, length(c + vec3(o, 0.0, 0.0)) - r);
    }
    return d;
}

float sdf(vec3 p) {
    const float halfSide = 0.66;
    float cube = sdRoundBox(p, vec3(halfSide), 0.13);
    // Each face: its value and its local frame (depth measured outwards from the face).
    float holes = 1e3;
    holes = min(holes, pips(p.yz, p.x - halfSide, 1));
    holes = min(holes, pips(p.yz, -p.x - halfSide, 6));
    holes = min(holes, pips(p.xz, p.y - halfSide, 2));
    holes = min(holes, pips(p.xz, -p.y - halfSide, 5));
    holes = min(holes, pips(p.xy, p.z - halfSide, 3));
    holes = min(holes, pips(p.xy, -p.z - halfSide, 4));
    return max(cube, -holes);
}
