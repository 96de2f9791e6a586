/* sdfwb
name: Rocket
category: Vehicle
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: A classic space rocket standing on its fins: a cylindrical body with an ogive nose
  (a tall ellipsoid cap), a ring of portholes facing +X, four swept fins (plates, by angular
  repetition), a flared nozzle and bands at the joints. Exact cylinders, frustums and tori and
  an ellipsoid bound, joined with min and smooth minimum: conservative.
*/
#include "../lib/modelling.glsl"

float sdf(vec3 p) {
    // Body and nose.
    float body = sdCylinder(p - vec3(0.0, -0.15, 0.0), 0.24, 0.45);
    float nose = sdEllipsoid(p - vec3(0.0, 0.3, 0.0), vec3(0.24, 0.58, 0.24));
    nose = max(nose, 0.3 - p.y);
    float rocket = smoothMin(body, nose, 0.02);
    float bands = min(sdTorus(p - vec3(0.0, 0.3, 0.0), 0.24, 0.02), sdTorus(p - vec3(0.0, -0.55, 0.0), 0.245, 0.025));
    rocket = min(rocket, bands);

    // Portholes: two round windows on the +X side (rims as tori, glass slightly recessed).
    vec3 w = p - vec3(0.235, 0.12, 0.0);
    float porthole = sdTorusYZ(w, 0.07, 0.018);
    w.y += 0.26;
    porthole = min(porthole, sdTorusYZ(w, 0.055, 0.016));
    rocket = min(rocket, porthole);

    // Fins: four swept plates around the base, rotated 45 degrees so one faces the camera.
    vec2 s = sectorFold(rotate2(p.xz, 0.785398), 4.0);
    vec2 outline = vec2(s.x, p.y);
    float finShape = sdTriangle2(outline, vec2(0.18, -0.1), vec2(0.18, -0.82), vec2(0.58, -0.82));
    finShape = min(finShape, sdBox2(outline - vec2(0.38, -0.86), vec2(0.2, 0.04)));
    float fins = sdPlate(finShape - 0.02, s.y, 0.025);
    rocket = smoothMin(rocket, fins, 0.03);

    // Nozzle under the body.
    float nozzle = sdFrustum(p - vec3(0.0, -0.7, 0.0), 0.18, 0.12, 0.1);
    float bore = sdFrustum(p - vec3(0.0, -0.74, 0.0), 0.15, 0.08, 0.1);
    nozzle = max(nozzle, -bore);
    return min(rocket, nozzle);
}
