/* sdfwb
name: Turtle
category: Animal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A tortoise walking towards +X: a domed shell covered in raised plates (a ring of
  bumps blended onto the dome with a tight smooth union, so creases show between plates)
  above a flat rim and belly plate, a head on a neck, four stubby legs and a short tail.
  Ellipsoid bounds, unions and smooth unions: conservative.
*/
#include "../lib/modelling.glsl"

const vec3 DOME_CENTRE = vec3(-0.05, -0.2, 0.0);
const vec3 DOME_RADII = vec3(0.64, 0.5, 0.52);

// A shell plate: a flattened bump sitting on the dome above (x, z).
float plate(vec3 p, float x, float z) {
    vec2 u = vec2(x, z) / DOME_RADII.xz;
    float y = DOME_RADII.y * sqrt(max(1.0 - dot(u, u), 0.0));
    vec3 c = DOME_CENTRE + vec3(x, y - 0.05, z);
    return sdEllipsoid(p - c, vec3(0.18, 0.08, 0.18));
}

float sdf(vec3 p) {
    // Shell: the upper half of an ellipsoid on a flat rim.
    float dome = sdEllipsoid(p - DOME_CENTRE, DOME_RADII);
    dome = max(dome, DOME_CENTRE.y - 0.02 - p.y);
    float rim = sdEllipsoid(p - DOME_CENTRE, vec3(0.68, 0.07, 0.56));
    float belly = sdEllipsoid(p - DOME_CENTRE - vec3(0.0, -0.06, 0.0), vec3(0.56, 0.1, 0.44));

    // Plates: a row of three along the spine and three down each flank.
    float plates = min(plate(p, -0.28, 0.0), min(plate(p, 0.0, 0.0), plate(p, 0.28, 0.0)));
    vec3 m = vec3(p.x, p.y, abs(p.z));
    plates = min(plates, min(plate(m, -0.3, 0.26), min(plate(m, 0.0, 0.3), plate(m, 0.3, 0.26))));
    float shell = smoothMin(dome, plates, 0.02);
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
