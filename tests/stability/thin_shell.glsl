// Stiff case: a paper-thin spherical shell, thickness 1e-4 (exact).
float sdf(vec3 p) { return abs(length(p) - 0.6) - 0.5e-4; }
