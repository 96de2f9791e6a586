/* sdfwb
name: Anvil
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A blacksmith's anvil with its horn towards +X: a flat working face with a square
  hardy hole and a round pritchel hole, a stepped table, a conical horn curving down from the
  front, a pinched waist and a splayed base with four feet. Boxes, frustums and round cones
  joined with min, max and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Face: the long flat top block; heel overhanging at -X.
    float face = sdRoundBox(p - vec3(-0.15, 0.32, 0.0), vec3(0.5, 0.12, 0.2), 0.02);
    float hardy = sdBox(p - vec3(-0.5, 0.32, 0.0), vec3(0.04, 0.2, 0.04));
    float pritchel = sdCylinder(p - vec3(-0.36, 0.32, 0.0), 0.025, 0.2);
    face = max(face, -min(hardy, pritchel));
    // Step (table) down to the horn.
    float table = sdRoundBox(p - vec3(0.4, 0.28, 0.0), vec3(0.08, 0.08, 0.14), 0.02);

    // Horn: a cone tapering to +X, flattened on top to the table height, drooping a little.
    float horn = sdRoundCone(p, vec3(0.42, 0.26, 0.0), vec3(0.9, 0.3, 0.0), 0.14, 0.02);
    horn = max(horn, p.y - 0.35);
    float top = min(min(face, table), horn);

    // Waist: a narrower block blended smoothly into the face above and the base below.
    float waist = sdBox(p - vec3(-0.12, -0.05, 0.0), vec3(0.16, 0.25, 0.09));
    // Base: a splayed block with a notch underneath forming four feet.
    float base = sdFrustum(p - vec3(-0.12, -0.45, 0.0), 0.42, 0.22, 0.12);
    base = max(base, sdBox(p - vec3(-0.12, -0.45, 0.0), vec3(0.42, 0.12, 0.3)));
    float notch = min(sdBox(p - vec3(-0.12, -0.58, 0.0), vec3(0.5, 0.06, 0.12)),
                      sdBox(p - vec3(-0.12, -0.58, 0.0), vec3(0.2, 0.06, 0.5)));
    base = max(base, -notch);

    float body = smoothMin(waist, base, 0.16);
    body = smoothMin(body, top, 0.14);
    return body;
}
