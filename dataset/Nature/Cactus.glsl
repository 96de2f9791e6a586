/* sdfwb
name: Saguaro Cactus
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A saguaro cactus on a sand mound: a ribbed main column and two bent arms. Each
  column is a ring of ten capsule ribs (angular repetition around its axis) filled by a
  slightly thinner core; the arms join the trunk through horizontal elbows. Exact capsules
  joined with min and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

// A vertical ribbed column centred on the local Y axis from y0 to y1, radius r.
float ribbedColumn(vec3 p, float y0, float y1, float r) {
    vec2 s = sectorFold(p.xz, 10.0);
    float rib = sdCapsule(vec3(s.x, p.y, s.y), vec3(0.78 * r, y0, 0.0), vec3(0.78 * r, y1, 0.0), 0.3 * r);
    float core = sdCapsule(p, vec3(0.0, y0, 0.0), vec3(0.0, y1, 0.0), 0.93 * r);
    return smoothMin(rib, core, 0.01);
}

float sdf(vec3 p) {
    float trunk = ribbedColumn(p, -0.82, 0.55, 0.2);

    // Right arm (towards +X): out, then up.
    float elbowR = sdCapsule(p, vec3(0.0, -0.12, 0.0), vec3(0.42, -0.12, 0.0), 0.11);
    float armR = ribbedColumn(p - vec3(0.44, 0.0, 0.0), -0.12, 0.3, 0.12);
    // Left arm (towards -X), higher and shorter.
    float elbowL = sdCapsule(p, vec3(0.0, 0.1, 0.0), vec3(-0.38, 0.1, 0.0), 0.1);
    float armL = ribbedColumn(p - vec3(-0.4, 0.0, 0.0), 0.1, 0.42, 0.11);
    float arms = min(smoothMin(elbowR, armR, 0.06), smoothMin(elbowL, armL, 0.06));

    float cactus = smoothMin(trunk, arms, 0.06);
    float sand = sdEllipsoid(p - vec3(0.0, -0.86, 0.0), vec3(0.55, 0.12, 0.55));
    return max(smoothMin(cactus, sand, 0.06), -0.9 - p.y);   // flat underneath
}
