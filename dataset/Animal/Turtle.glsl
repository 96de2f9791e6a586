/* sdfwb
name: Turtle
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A tortoise walking towards +X: a domed shell divided into plates by shallow grooves
  (thin slabs carved only near the dome's surface), above a flat rim and belly plate, a head on a neck, four stubby legs and a short tail.
  Ellipsoid bounds, unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

const vec3 DOME_CENTRE = vec3(-0.05, -0.2, 0.0);
const vec3 DOME_RADII = vec3(0.64, 0.5, 0.52);

float sdf(vec3 p) {
    // Shell: the upper half of an ellipsoid on a flat rim.
    float dome = sdEllipsoid(p - DOME_CENTRE, DOME_RADII);
    dome = max(dome, DOME_CENTRE.y - 0.02 - p.y);
    float rim = sdEllipsoid(p - DOME_CENTRE, vec3(0.68, 0.07, 0.56));
    float belly = sdEllipsoid(p - DOME_CENTRE - vec3(0.0, -0.06, 0.0), vec3(0.56, 0.1, 0.44));

    // Plates: shallow grooves cut into the dome along four vertical planes and one level ring
    // split it into scutes. A groove removes the part of a thin slab that lies within `depth`
    // of the dome's surface.
    vec3 m = vec3(p.x, p.y, abs(p.z));
    float slabs = min(abs(abs(p.x + 0.04) - 0.2), abs(m.z - 0.19));
    slabs = min(slabs, abs(p.y + 0.02)) - 0.012;
    float groove = max(slabs, -dome - 0.025);
    float shell = smoothSubtract(dome, groove, 0.01);
    shell = smoothMin(shell, min(rim, belly), 0.04);

    // Head and neck poking out in front, with eyes.
    float neck = sdRoundCone(p, vec3(0.45, -0.25, 0.0), vec3(0.72, -0.12, 0.0), 0.11, 0.1);
    float head = sdEllipsoid(p - vec3(0.78, -0.08, 0.0), vec3(0.17, 0.12, 0.12));
    float body = smoothMin(neck, head, 0.06);
    float eye = sdSphere(m - vec3(0.84, -0.02, 0.08), 0.03);
    body = min(body, eye);

    // Four stubby legs angled out and down, and a short pointed tail.
    vec3 l = vec3(abs(p.x + 0.05), p.y, abs(p.z));
    float leg = sdRoundCone(l, vec3(0.3, -0.26, 0.28), vec3(0.4, -0.46, 0.42), 0.12, 0.1);
    float tail = sdRoundCone(p, vec3(-0.6, -0.26, 0.0), vec3(-0.8, -0.33, 0.0), 0.06, 0.015);
    body = smoothMin(body, min(leg, tail), 0.04);

    return smoothMin(shell, body, 0.05);
}
