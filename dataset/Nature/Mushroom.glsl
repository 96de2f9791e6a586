/* sdfwb
name: Toadstools
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Two fly-agaric toadstools on a patch of moss: each has a domed cap with a hollowed
  underside, raised round spots, a thick stem swelling at the foot and a hanging ring.
  The cap is an ellipsoid dome minus a lower ellipsoid; spots are small spheres set into the
  cap surface. Ellipsoid bounds, intersections and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

// One toadstool of unit-ish size standing at the origin, cap centre at height `h`.
float toadstool(vec3 p, float h, float capRadius) {
    // Cap: a dome with a hollowed underside.
    vec3 c = p - vec3(0.0, h, 0.0);
    float dome = sdEllipsoid(c, vec3(capRadius, 0.62 * capRadius, capRadius));
    float hollow = sdEllipsoid(c + vec3(0.0, 0.12 * capRadius, 0.0), vec3(0.92 * capRadius, 0.4 * capRadius, 0.92 * capRadius));
    float cap = max(dome, -hollow);
    cap = max(cap, -c.y - 0.05 * capRadius);

    // Spots: bumps on the cap on two rings (angular repetition), plus one on top.
    vec2 s1 = sectorFold(c.xz, 6.0);
    float spots = sdSphere(vec3(s1.x - 0.62 * capRadius, c.y - 0.45 * capRadius, s1.y), 0.13 * capRadius);
    vec2 s2 = sectorFold(rotate2(c.xz, 0.5236), 6.0);
    spots = min(spots, sdSphere(vec3(s2.x - 0.88 * capRadius, c.y - 0.22 * capRadius, s2.y), 0.1 * capRadius));
    spots = min(spots, sdSphere(c - vec3(0.0, 0.62 * capRadius, 0.0), 0.14 * capRadius));
    cap = smoothMin(cap, spots, 0.03 * capRadius);

    // Stem: swelling at the foot, with a skirt ring under the cap.
    float stem = sdRoundCone(p, vec3(0.0, 0.08 * capRadius, 0.0), vec3(0.0, h, 0.0), 0.3 * capRadius, 0.2 * capRadius);
    float ring = sdTorus(p - vec3(0.0, h - 0.25 * capRadius, 0.0), 0.24 * capRadius, 0.04 * capRadius);
    return min(cap, smoothMin(stem, ring, 0.03));
}

float sdf(vec3 p) {
    float big = toadstool(p - vec3(0.1, -0.72, -0.1), 1.0, 0.62);
    float small = toadstool(p - vec3(-0.42, -0.72, 0.42), 0.5, 0.3);
    float moss = sdEllipsoid(p - vec3(-0.05, -0.78, 0.05), vec3(0.75, 0.09, 0.75));
    return smoothMin(min(big, small), moss, 0.08);
}
