/* sdfwb
name: Solid Angle
category: Geometry
type: exact
animated: no
author: sdfwb authors
license: CC0-1.0
notes: The part of a ball of radius 1.45 inside a cone of half angle 38 degrees with the same apex:
  a sharp-tipped cone capped by a spherical dome, apex down at y = -0.725. In the meridian
  half-plane the profile is a circular sector, whose boundary is the slanted radius and the arc.
  The exact distance to those two pieces, signed by a point-in-sector test, is the exact 3D distance
  (the axis is interior, not boundary).
*/
float sdf(vec3 p) {
    const float radius = 1.45;
    const vec2 rimDirection = vec2(0.61566148, 0.78801075);  // (sin 38, cos 38) from the apex
    const float apexHeight = -0.725;
    vec2 q = vec2(length(p.xz), p.y - apexHeight);

    float fromApex = length(q);
    // Positive when q lies outside the cone's half angle.
    float outsideCone = rimDirection.y * q.x - rimDirection.x * q.y;
    // Distance to the arc counts only where the point's direction falls within the cone; elsewhere
    // the arc's nearest point is its rim, which the slanted segment already covers.
    float toArc = outsideCone <= 0.0 ? abs(fromApex - radius) : 1e10;
    float toSide = length(q - rimDirection * clamp(dot(q, rimDirection), 0.0, radius));
    float distanceToSurface = min(toArc, toSide);
    bool inside = fromApex < radius && outsideCone < 0.0;
    return inside ? -distanceToSurface : distanceToSurface;
}
