/* sdfwb
name: Lighthouse
category: Manufactured
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A striped lighthouse on a rock: a tapered tower with raised bands every other
  stripe, a door facing +X, a gallery deck with a railing of posts (angular repetition) and
  a top rail, a glazed lantern room with mullions and a domed roof with a finial. Exact
  frustums, cylinders, tori and boxes joined with min and max; the rock is an ellipsoid bound.
  Conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Tower: a frustum from y = -0.7 to y = 0.35.
    vec3 t = p - vec3(0.0, -0.175, 0.0);
    float tower = sdFrustum(t, 0.32, 0.2, 0.525);
    // Raised bands: the same frustum 0.015 fatter, kept only in alternate horizontal slices.
    float bandY = clamp(round((p.y + 0.53) / 0.3), 0.0, 2.0) * 0.3 - 0.53;
    float band = max(sdFrustum(t, 0.335, 0.215, 0.525), abs(p.y - bandY) - 0.075);
    tower = min(tower, band);
    // Door at the foot, facing +X.
    float door = sdBox(p - vec3(0.32, -0.58, 0.0), vec3(0.06, 0.1, 0.06));
    door = min(door, sdCylinderX(p - vec3(0.32, -0.48, 0.0), 0.06, 0.06));
    tower = max(tower, -door);

    // Gallery: a deck disc, a ring of posts and a top rail.
    float deck = sdCylinder(p - vec3(0.0, 0.37, 0.0), 0.3, 0.025);
    vec2 s = sectorFold(p.xz, 16.0);
    float posts = sdCapsule(vec3(s.x, p.y, s.y), vec3(0.28, 0.39, 0.0), vec3(0.28, 0.5, 0.0), 0.01);
    float rail = sdTorus(p - vec3(0.0, 0.5, 0.0), 0.28, 0.012);
    float gallery = min(deck, min(posts, rail));

    // Lantern room: glass cylinder with mullions, a roof dome and a finial.
    float glass = sdCylinder(p - vec3(0.0, 0.52, 0.0), 0.16, 0.13);
    vec2 g = sectorFold(p.xz, 8.0);
    float mullions = sdBox(vec3(g.x - 0.165, p.y - 0.52, g.y), vec3(0.012, 0.13, 0.012));
    float roof = sdEllipsoid(p - vec3(0.0, 0.65, 0.0), vec3(0.21, 0.16, 0.21));
    roof = max(roof, 0.65 - p.y);
    float finial = sdRoundCone(p, vec3(0.0, 0.78, 0.0), vec3(0.0, 0.88, 0.0), 0.03, 0.01);
    float lantern = min(min(glass, mullions), min(roof, finial));

    // Rock the tower stands on.
    float rock = sdEllipsoid(p - vec3(0.0, -0.78, 0.0), vec3(0.6, 0.14, 0.55));
    rock = max(rock, -0.88 - p.y);
    return min(min(tower, gallery), min(lantern, rock));
}
