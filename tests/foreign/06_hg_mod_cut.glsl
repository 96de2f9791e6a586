// Imitates: hg_sdf-based demo code -- the library #included, pMod1 on a
// component, fBoxCheap/vmax helpers, and the entry named `sdScene`, as in
// some tutorials (no sdf() in this file).
//
// Why discontinuous: pMod1 repeats space in x with cells 0.4 wide, but the
// bar drawn in each cell is centred 0.1 off the cell centre and has radius
// 0.2, so it pokes 0.1 out of its cell and is cut by the cell face. On the
// face x = 0.2 + 0.4*n the left cell measures the bar 0.1 away from its
// axis and the right cell 0.3 away: on the plane y = 0 the field jumps from
// -0.1 to +0.1, and by more than 1e-3 over the whole face inside the clip
// box (|x| < 0.8, |z| < 0.7, faces at x = +-0.2 and +-0.6). A centred
// (mirror-symmetric) bar would not jump even if it were too wide; the
// offset is what breaks it. Otherwise 1-Lipschitz, finite and bounded.
// expect: entry=sdScene flags=discontinuous animated=no

#include "lib/hg_style.glsl"

float sdScene(vec3 p) {
	vec3 q = p;
	pMod1(q.x, 0.4);
	// bar along z, off-centre in its cell
	float bar = length(q.xy - vec2(0.1, 0.)) - 0.2;
	// clip to a box inside the cube
	return max(bar, fBoxCheap(p, vec3(0.8, 0.5, 0.7)));
}
