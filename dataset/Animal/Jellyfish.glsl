/* sdfwb
name: Jellyfish
category: Animal
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A jellyfish pulsing with a 3 s period: a hollow dome bell (outer ellipsoid minus a
  lowered inner one) that squeezes and relaxes, with a rim bead, four thick oral arms under
  the centre and eight thin trailing tentacles that ripple. Arms and tentacles are tubes
  whose centre lines wave sideways: the wave slope (at most 0.3) and taper (0.03) are divided
  out, so every part has gradient at most 1; unions and smooth unions make it conservative.
*/
#include "../lib/modelling.glsl"

// A hanging tube from y = top to y = bottom whose centre sits at radial offset
// `offset + amp * sin(freq * y + phase)` in sector coordinates (u radial, v tangential).
float wavyTube(vec2 uv, float y, float offset, float top, float bottom, float rTop, float rBottom,
               float amp, float freq, float phase) {
    float yc = clamp(y, bottom, top);
    float along = (top - yc) / (top - bottom);
    float centre = offset + amp * sin(freq * yc + phase) * along;
    float radius = mix(rTop, rBottom, along);
    float d = length(vec3(uv.x - centre, y - yc, uv.y)) - radius;
    // Slope of the centre line: amp*freq + amp/(top-bottom); slope of the radius: taper.
    float slope = amp * freq + amp / (top - bottom) + abs(rTop - rBottom) / (top - bottom);
    return d / (1.0 + slope);
}

float sdf(vec3 p, float time) {
    float phase = 6.2831853 * time / 3.0;
    float squeeze = sin(phase);               // > 0: bell contracts (narrower, taller)

    // Bell: a dome shell. Radii breathe in opposite directions to keep the volume plausible.
    float radius = 0.6 * (1.0 - 0.08 * squeeze);
    float height = 0.45 * (1.0 + 0.08 * squeeze);
    vec3 c = p - vec3(0.0, 0.2, 0.0);
    float outer = sdEllipsoid(c, vec3(radius, height, radius));
    float inner = sdEllipsoid(c + vec3(0.0, 0.1, 0.0), vec3(radius - 0.07, height - 0.06, radius - 0.07));
    float bell = max(outer, -inner);
    bell = max(bell, -c.y - 0.02);              // open underneath
    // A soft bead along the rim.
    float rim = sdTorus(c + vec3(0.0, 0.02, 0.0), radius - 0.035, 0.035);
    bell = smoothMin(bell, rim, 0.03);

    // Oral arms: four thick frilly tubes hanging under the centre.
    vec2 armUV = sectorFold(p.xz, 4.0);
    float arms = wavyTube(armUV, p.y, 0.1, 0.15, -0.6, 0.07, 0.03, 0.05, 5.0, -phase);

    // Tentacles: eight thin tubes from under the rim, rippling.
    vec2 tenUV = sectorFold(rotate2(p.xz, 0.3927), 8.0);
    float tentacles = wavyTube(tenUV, p.y, radius - 0.1, 0.2, -0.9, 0.025, 0.012, 0.05, 4.5,
                               -phase + 1.0);

    float jelly = smoothMin(bell, arms, 0.06);
    return min(jelly, tentacles);
}
