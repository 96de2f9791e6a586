/* sdfwb
name: Menger Sponge
category: Fractal
type: conservative
animated: no
author: sdfwb authors
license: CC0-1.0
notes: Menger sponge of half size 0.78, four levels. Level k removes a cross of three square bars
  (half width one sixth of the cell) through the centre of every cell of size 2 / 3^(k-1); within
  a level the nearest bar always belongs to the point's own cell, so the cell-wrapped exact distance
  to the cross is the exact distance to all crosses of that level. The sponge is the box minus every
  cross: the maximum of the exact box distance and the negated cross distances. Each term is
  1-Lipschitz and continuous, and max() keeps that, but intersection and subtraction are only
  bounds, so the field is conservative (exact where one term alone decides).
*/
// Exact distance to an infinite bar of square cross-section (half width `halfWidth`) whose axis
// is perpendicular to the plane of `across`.
float barDistance(vec2 across, float halfWidth) {
    vec2 overshoot = abs(across) - halfWidth;
    return length(max(overshoot, 0.0)) + min(max(overshoot.x, overshoot.y), 0.0);
}

float sdf(vec3 p) {
    const float halfSize = 0.78;
    const int levels = 4;
    vec3 q = p / halfSize;  // the sponge in [-1, 1]^3

    vec3 overshoot = abs(q) - 1.0;
    float solid = length(max(overshoot, 0.0)) + min(max(overshoot.x, max(overshoot.y, overshoot.z)), 0.0);

    float cellSize = 2.0;
    for (int level = 0; level < levels; ++level) {
        // Position relative to the centre of the point's cell (cells tile space from the corner -1).
        vec3 local = mod(q + 1.0, cellSize) - 0.5 * cellSize;
        float halfWidth = cellSize / 6.0;
        float cross = min(barDistance(local.yz, halfWidth),
                          min(barDistance(local.xz, halfWidth), barDistance(local.xy, halfWidth)));
        solid = max(solid, -cross);
        cellSize /= 3.0;
    }
    return solid * halfSize;
}
