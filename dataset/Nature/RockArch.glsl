/* sdfwb
name: Rock Arch
category: Nature
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A natural sandstone arch on a rocky base. The arch is a half torus in the XY plane
  with a thick, flattened cross-section, standing on two boulder legs and a slab; a
  weathering displacement (six plane sine waves in unrelated directions, wave numbers 7 to 22,
  amplitudes 0.035 down to 0.007) roughens the surface. The displacement adds at most
  sum(amplitude * wave number) = 1.19 to the gradient, so the rock field is divided by 2.19. Unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

// Weathering: six plane waves in unrelated directions (wave vectors k, amplitudes a); its
// gradient is at most sum(a |k|) = 1.19.
float weathering(vec3 p) {
    float n = 0.035 * sin(dot(p, vec3(5.1, 3.2, -4.0)) + 0.3);
    n += 0.03 * sin(dot(p, vec3(-3.0, 6.5, 2.5)) + 1.9);
    n += 0.018 * sin(dot(p, vec3(9.0, -4.0, 6.0)) + 4.0);
    n += 0.016 * sin(dot(p, vec3(-7.0, -8.0, -5.0)) + 2.6);
    n += 0.008 * sin(dot(p, vec3(14.0, 9.0, -11.0)));
    n += 0.007 * sin(dot(p, vec3(-12.0, 15.0, 10.0)) + 5.1);
    return n;
}

float rock(vec3 p) {
    // Arch: a half ring above y = -0.3; its cross-section is wider in z than in the ring plane.
    vec3 a = p - vec3(0.0, -0.35, 0.0);
    vec2 ring = vec2(length(a.xy) - 0.6, a.z);
    float arch = sdEllipsoid(vec3(ring, 0.0), vec3(0.17, 0.26, 1.0));   // an ellipse in (ring, z)
    arch = max(arch, -a.y);
    // Legs: boulders under each end of the arch.
    float legR = sdEllipsoid(p - vec3(0.6, -0.45, 0.0), vec3(0.25, 0.3, 0.3));
    float legL = sdEllipsoid(p - vec3(-0.6, -0.45, 0.02), vec3(0.26, 0.32, 0.31));
    // Base slab the arch stands on.
    float slab = sdRoundBox(p - vec3(0.0, -0.75, 0.0), vec3(0.88, 0.1, 0.42), 0.08);
    float r = smoothMin(arch, min(legR, legL), 0.12);
    return smoothMin(r, slab, 0.1);
}

float sdf(vec3 p) {
    return (rock(p) + weathering(p)) / 2.19;
}
