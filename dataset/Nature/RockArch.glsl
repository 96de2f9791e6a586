/* sdfwb
name: Rock Arch
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A natural sandstone arch on a rocky base. The arch is a half torus in the XY plane
  with a thick, flattened cross-section, standing on two boulder legs and a slab; a low
  frequency weathering displacement (sum of three sine products of amplitude 0.03, 0.02 and
  0.012 with wave numbers about 7, 12 and 21) roughens the surface. The displacement adds at
  most 0.03*12.2 + 0.02*20.8 + 0.012*36.4 = 1.22 to the gradient, so the rock field is divided
  by 2.22. Unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

float weathering(vec3 p) {
    float n = 0.03 * sin(7.0 * p.x + 1.0) * sin(7.0 * p.y + 2.0) * sin(7.0 * p.z);
    n += 0.02 * sin(12.0 * p.x) * sin(12.0 * p.y + 1.3) * sin(12.0 * p.z + 0.7);
    n += 0.012 * sin(21.0 * p.x + 0.4) * sin(21.0 * p.y) * sin(21.0 * p.z + 2.1);
    return n;
}

float rock(vec3 p) {
    // Arch: a half ring above y = -0.3; its cross-section is wider in z than in the ring plane.
    vec3 a = p - vec3(0.0, -0.35, 0.0);
    vec2 ring = vec2(length(a.xy) - 0.6, a.z);
    float arch = sdEllipsoid(vec3(ring, 0.0), vec3(0.15, 0.24, 1.0));   // an ellipse in (ring, z)
    arch = max(arch, -a.y);
    // Legs: boulders under each end of the arch.
    float legR = sdEllipsoid(p - vec3(0.6, -0.45, 0.0), vec3(0.2, 0.28, 0.27));
    float legL = sdEllipsoid(p - vec3(-0.6, -0.45, 0.02), vec3(0.21, 0.3, 0.28));
    // Base slab the arch stands on.
    float slab = sdRoundBox(p - vec3(0.0, -0.75, 0.0), vec3(0.88, 0.1, 0.42), 0.08);
    float r = smoothMin(arch, min(legR, legL), 0.12);
    return smoothMin(r, slab, 0.1);
}

float sdf(vec3 p) {
    return (rock(p) + weathering(p)) / 2.22;
}
