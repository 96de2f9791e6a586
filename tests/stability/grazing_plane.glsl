// Rays grazing a plane: the half-space y < -0.3 (exact). Seen from just above it, rays near the
// horizon approach the plane at a tiny angle and sphere tracing crawls: each step shrinks the
// remaining height by sin(angle) only.
float sdf(vec3 p) { return p.y + 0.3; }
