// Imitates: demo code built on the Mercury hg_sdf library -- the library
// #included, p* operators rewriting the point in place (pModPolar on a
// swizzle), f* primitives and fOpUnionRound fillets, TAU from the library's
// #defines, and the entry named `scene` (no sdf() in this file).
//
// Why the audit should find it clean: pModPolar is a piecewise rotation;
// each column is centred on its sector's mid-line and mirror-symmetric
// about it, so neighbouring sectors agree on the seams (continuous) and
// the field stays 1-Lipschitz. fOpUnionRound is 1-Lipschitz where the two
// gradients meet at right angles, which is the case here: the columns are
// endless vertical cylinders (horizontal gradient) and they meet the two
// discs only through their flat faces (vertical gradient); the disc rims
// (horizontal gradient) are 0.13 beyond the columns, more than the fillet
// radius. A final max() with a slab clips the columns; max keeps it
// 1-Lipschitz and bounded.
// expect: entry=scene flags=none animated=no

#include "lib/hg_style.glsl"

#define COLUMNS 8.
#define FILLET 0.05

float scene(vec3 p) {
	// floor and roof discs
	float floorDisc = fCylinder(p - vec3(0., -0.675, 0.), 0.8, 0.075);
	float roofDisc  = fCylinder(p - vec3(0.,  0.675, 0.), 0.8, 0.075);

	// columns: one per sector, endless in y
	vec3 q = p;
	float sector = pModPolar(q.xz, COLUMNS);
	float column = length(q.xz - vec2(0.55, 0.)) - 0.07;

	float d = fOpUnionRound(column, floorDisc, FILLET);
	d = fOpUnionRound(d, roofDisc, FILLET);

	// clip the endless columns at the outer faces of the discs
	return max(d, abs(p.y) - 0.75);
}
