// A zero set with a vanishing gradient: f = (|p| - 0.5)^3. |grad f| = 0 on the surface.
float sdf(vec3 p) { float d = length(p) - 0.5; return d * d * d; }
