/* sdfwb
name: Chess Rook
category: Misc
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A Staunton-style rook: a stepped round base with a bead, a waisted tower (a frustum
  with rings), and a turret with a hollow top and four battlements (notches cut by boxes in
  angular repetition). Solids of revolution, exact each, joined with min and max:
  conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Base: a wide disc, a smaller step and a bead ring.
    float base = sdCylinder(p - vec3(0.0, -0.82, 0.0), 0.5, 0.06) - 0.02;
    base = min(base, sdFrustum(p - vec3(0.0, -0.68, 0.0), 0.44, 0.36, 0.08));
    base = min(base, sdTorus(p - vec3(0.0, -0.58, 0.0), 0.34, 0.04));
    // Tower: tapering upwards, then flaring into the turret.
    float tower = sdFrustum(p - vec3(0.0, -0.15, 0.0), 0.32, 0.24, 0.42);
    float collar = sdTorus(p - vec3(0.0, 0.3, 0.0), 0.26, 0.035);
    float flare = sdFrustum(p - vec3(0.0, 0.42, 0.0), 0.25, 0.36, 0.1);
    // Turret: a cylinder with a hollow top and four notches.
    float turret = sdCylinder(p - vec3(0.0, 0.62, 0.0), 0.36, 0.16) - 0.01;
    float hollow = sdCylinder(p - vec3(0.0, 0.8, 0.0), 0.25, 0.12);
    vec2 s = sectorFold(rotate2(p.xz, 0.785398), 4.0);
    float notch = sdBox(vec3(s.x - 0.3, p.y - 0.8, s.y), vec3(0.15, 0.1, 0.07));
    turret = max(turret, -min(hollow, notch));
    float rook = smoothMin(min(base, tower), collar, 0.03);
    return min(rook, smoothMin(flare, turret, 0.02));
}
