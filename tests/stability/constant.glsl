// A constant field: no surface at all.
float sdf(vec3 p) { return 0.7; }
