/* sdfwb
name: Flying Saucer
category: Vehicle
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A flying saucer hovering (bobbing and tilting with a 4 s period) while its ring of
  lights circles the rim (one light spacing per second, so it loops): a lens-shaped hull from
  two intersecting spheres, a rim band, a glass dome with a collar, ten lights on the rim and
  three landing legs with pads. The motion is rigid; the lights are a rigid rotation of a
  symmetric element repeated by angular repetition. Exact parts: conservative.
*/
#include "../lib/modelling.glsl"

float saucer(vec3 p, float time) {
    // Hull: the lens shared by two large spheres, one above and one below.
    // The two spheres meet on a circle of radius 0.709 at y = 0.022, where the band sits.
    float lens = max(sdSphere(p - vec3(0.0, -1.3, 0.0), 1.5), sdSphere(p - vec3(0.0, 1.4, 0.0), 1.55));
    float band = sdTorus(p - vec3(0.0, 0.022, 0.0), 0.71, 0.045);
    float hull = smoothMin(lens, band, 0.03);
    // Dome and its collar.
    float dome = sdSphere(p - vec3(0.0, 0.2, 0.0), 0.3);
    dome = max(dome, 0.15 - p.y);
    float collar = sdTorus(p - vec3(0.0, 0.2, 0.0), 0.3, 0.03);
    // Lights: ten bumps on the rim band, circling.
    vec2 l = sectorFold(rotate2(p.xz, MODEL_TAU * 0.1 * time), 10.0);
    float lights = sdSphere(vec3(l.x - 0.755, p.y - 0.022, l.y), 0.05);
    // Landing legs: three splayed struts with round pads.
    vec2 g = sectorFold(p.xz, 3.0);
    float leg = sdCapsule(vec3(g.x, p.y, g.y), vec3(0.3, -0.05, 0.0), vec3(0.52, -0.4, 0.0), 0.025);
    float pad = sdCylinder(vec3(g.x, p.y, g.y) - vec3(0.52, -0.42, 0.0), 0.07, 0.015);
    return min(min(hull, min(dome, collar)), min(lights, min(leg, pad)));
}

float sdf(vec3 p, float time) {
    float phase = MODEL_TAU * time / 4.0;
    vec3 q = p - vec3(0.0, 0.1 + 0.05 * sin(phase), 0.0);
    q.xy = rotate2(q.xy, 0.06 * sin(phase + 1.0));
    q.yz = rotate2(q.yz, 0.06 * cos(phase));
    return saucer(q, time);
}
