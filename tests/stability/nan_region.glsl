// Broken case: NaN for x > 0.6 (sqrt of a negative), a sphere elsewhere.
float sdf(vec3 p) { return p.x > 0.6 ? sqrt(-1.0 - p.x) : length(p) - 0.5; }
