// Imitates: hg_sdf demo style -- library #included, pR() on a swizzle to
// twist space (the hg way of writing opTwist: rotate p.xz by an angle that
// grows with p.y), pModPolar for a bundle of pipes, fTorus collars,
// pMirror, and the plain `float sdf(vec3 p)` entry.
//
// Why non-conservative: rotating p.xz by TWIST*p.y moves a point at radius
// rho around the axis by TWIST*rho per unit of height. Near a pipe (axis
// at radius 0.35, radius 0.1) the sideways motion, measured along the
// pipe's gradient, is up to ~0.35 per unit of height times TWIST, so
// |grad f| reaches about sqrt(1 + (4*0.35)^2) ~ 1.7, far above 1.05, beside
// the pipes. The pipes themselves are symmetric in their sectors
// (continuous), the torus collars are rotation-invariant (the twist does
// not affect them), everything is finite and clipped to |y| < 0.8.
// expect: entry=sdf flags=non-conservative animated=no

#include "lib/hg_style.glsl"

#define TWIST 4.0

float pipes(vec3 p) {
	pR(p.xz, TWIST*p.y);
	pModPolar(p.xz, 3.);
	return length(p.xz - vec2(0.35, 0.)) - 0.1;
}

float collars(vec3 p) {
	// mirror so one torus serves both ends
	pMirror(p.y, 0.65);
	return fTorus(p, 0.06, 0.35);
}

float sdf(vec3 p) {
	float d = min(pipes(p), collars(p));
	return max(d, abs(p.y) - 0.8);
}
