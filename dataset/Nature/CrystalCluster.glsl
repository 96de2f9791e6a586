/* sdfwb
name: Crystal Cluster
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A cluster of quartz crystals growing out of a rock: eight hexagonal prisms of
  different lengths and tilts, each capped with a six-sided pyramid, fanning out from a lumpy
  base. A crystal is the intersection of three slabs (the hexagon), a floor plane and a
  pyramid cap whose plane equation is normalised; intersections by max are bounds outside,
  so the field is conservative.
*/
#include "../lib/modelling.glsl"

// Crystal along +Y from y = 0: hexagon apothem r, total length len, pyramid tip of height tip.
float crystal(vec3 q, float r, float len, float tip) {
    const vec2 n1 = vec2(0.8660254, 0.5), n2 = vec2(0.8660254, -0.5);
    float radial = max(abs(q.z), max(abs(dot(q.xz, n1)), abs(dot(q.xz, n2))));
    float prism = max(radial - r, -q.y);
    // Pyramid: the cap planes pass through the prism edge at height len - tip and the apex.
    float k = tip / r;
    float cap = (k * radial + q.y - len) / sqrt(1.0 + k * k);
    return max(prism, cap);
}

// A crystal rooted at `base`, tilted by `tilt` away from vertical towards azimuth `azimuth`.
float placed(vec3 p, vec3 base, float azimuth, float tilt, float r, float len) {
    vec3 q = p - base;
    q.xz = rotate2(q.xz, azimuth);
    q.xy = rotate2(q.xy, tilt);
    return crystal(q, r, len, 1.6 * r);
}

float sdf(vec3 p) {
    vec3 b = vec3(0.0, -0.55, 0.0);
    float c = placed(p, b, 0.0, 0.0, 0.16, 1.3);
    c = min(c, placed(p, b + vec3(0.08, 0.0, 0.05), 0.3, -0.55, 0.12, 1.0));
    c = min(c, placed(p, b + vec3(-0.05, 0.0, 0.08), 2.4, -0.5, 0.11, 0.95));
    c = min(c, placed(p, b + vec3(0.0, 0.0, -0.08), -2.0, -0.6, 0.1, 0.85));
    c = min(c, placed(p, b, 1.3, -0.85, 0.09, 0.75));
    c = min(c, placed(p, b, -0.9, -0.9, 0.08, 0.7));
    c = min(c, placed(p, b, 3.6, -1.0, 0.08, 0.62));
    c = min(c, placed(p, b + vec3(0.05, 0.0, 0.0), 0.6, -0.25, 0.09, 1.05));

    // Rock base: two flattened lumps.
    float rock = sdEllipsoid(p - vec3(0.0, -0.7, 0.0), vec3(0.5, 0.2, 0.45));
    rock = smoothMin(rock, sdEllipsoid(p - vec3(0.25, -0.75, -0.2), vec3(0.3, 0.15, 0.28)), 0.08);
    return min(c, rock);
}
