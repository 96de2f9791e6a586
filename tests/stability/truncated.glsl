// A truncated field: the sphere's distance capped at 0.2 (common in SDF datasets built from
// narrow-band grids). Conservative, but useless far away: the audit reports where it saturates.
float sdf(vec3 p) { return min(length(p) - 0.5, 0.2); }
