// A discontinuous field: a 0.05 jump across the plane x = 0.1.
float sdf(vec3 p) { return length(p) - 0.5 + (p.x > 0.1 ? 0.05 : 0.0); }
