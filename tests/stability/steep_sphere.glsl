// Stiff case: 100 x a sphere's distance. |grad f| = 100: non-conservative; sphere tracing needs
// a step factor of 0.01; samplers still find the surface.
float sdf(vec3 p) { return 100.0 * (length(p) - 0.5); }
