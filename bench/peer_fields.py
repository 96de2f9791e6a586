"""NumPy float32 signed distance fields for the meshing benchmark's peers (bench/bench_mesh_peers.py).

Each field is `name(x, y, z)`: x, y, z are float32 arrays that broadcast (x along the last axis, e.g. shapes (1, 1, N),
(1, N, 1), (M, 1, 1), or three (N,) columns), and the result is a float32 array of the broadcast shape. Every constant
is an np.float32 so that nothing is promoted to float64; the GLSL is followed operation by operation where the order
changes float results. GLSL semantics: mod(a, b) = a - b * floor(a / b) (glsl_mod), mix(a, b, t) = a (1 - t) + b t,
clamp = min(max(v, lo), hi), sign = np.sign (0 at 0).

FIELDS maps sdfwb's names to the fields, SDFWB_SOURCES the same names to what sdfwb takes for them (a dataset name,
a foreign file's path or GLSL text), and GLSL_SOURCES holds the GLSL text of the three shapes written for the bench.

The post-processing a peer gets (Newton steps, refinement) is in the C++ peer, bench/device/flying_edges_peer.cpp.
"""
import os

import numpy as np

F = np.float32
ZERO, HALF, ONE, TWO = F(0.0), F(0.5), F(1.0), F(2.0)
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOREIGN = os.path.join(ROOT, "tests", "foreign")


# --- GLSL built-ins and small helpers (vectorised, float32) -------------------------------------------------------

def length2(x, y):
    return np.sqrt(x * x + y * y)


def length3(x, y, z):
    return np.sqrt(x * x + y * y + z * z)


def clamp(v, lo, hi):
    return np.minimum(np.maximum(v, F(lo)), F(hi))


def glsl_mod(a, b):
    """GLSL mod: a - b * floor(a / b) (the sign of b, unlike np.fmod)."""
    return a - b * np.floor(a / b)


def mix(a, b, t):
    """GLSL mix: a * (1 - t) + b * t."""
    return a * (ONE - t) + b * t


def full(*arrays):
    """The arrays broadcast to their common shape (for np.where swaps that exchange components)."""
    return np.broadcast_arrays(*arrays)


# --- The fields that were in bench/bench_mesh_peers.py ------------------------------------------------------------

# sphere: radius 0.8 (dataset/Geometry/Sphere.glsl).
def np_sphere(x, y, z):
    return np.sqrt(x * x + y * y + z * z) - np.float32(0.8)


# torus: the dataset's Torus, tilted 30 degrees about x (dataset/Geometry/Torus.glsl).
def np_torus(x, y, z):
    c, s = np.float32(0.8660254), np.float32(0.5)
    y, z = c * y + s * z, -s * y + c * z
    q = np.sqrt(x * x + z * z) - np.float32(0.65)
    return np.sqrt(q * q + y * y) - np.float32(0.25)


def np_box_of(x, y, z, hx, hy, hz):
    qx, qy, qz = np.abs(x) - np.float32(hx), np.abs(y) - np.float32(hy), np.abs(z) - np.float32(hz)
    outside = np.sqrt(np.maximum(qx, 0) ** 2 + np.maximum(qy, 0) ** 2 + np.maximum(qz, 0) ** 2)
    return outside + np.minimum(np.maximum(qx, np.maximum(qy, qz)), 0)


# box: half extents (0.8, 0.5, 0.6) (dataset/Geometry/Box.glsl).
def np_box(x, y, z):
    return np_box_of(x, y, z, 0.8, 0.5, 0.6)


# A rotation by an irrational angle (0.3 rad about (1, 2, 3)), rows of R^T for the fields below.
def rotation(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


TILT = rotation((1.0, 2.0, 3.0), 0.3)
T = TILT.T.astype(np.float32)  # the field is the upright shape's at R^T p


def untilt(x, y, z):
    return (T[0, 0] * x + T[0, 1] * y + T[0, 2] * z, T[1, 0] * x + T[1, 1] * y + T[1, 2] * z,
            T[2, 0] * x + T[2, 1] * y + T[2, 2] * z)


# rotated-box: a box of half extents (0.55, 0.4, 0.3) turned by TILT (GLSL_SOURCES["rotated-box"]).
def np_rotated_box(x, y, z):
    return np_box_of(*untilt(x, y, z), 0.55, 0.4, 0.3)


# rotated-cylinder: a capped cylinder along the tilted y axis, radius 0.45, half height 0.6
# (GLSL_SOURCES["rotated-cylinder"]).
def np_rotated_cylinder(x, y, z):
    u, v, w = untilt(x, y, z)
    dx, dy = np.sqrt(u * u + w * w) - np.float32(0.45), np.abs(v) - np.float32(0.6)
    return np.minimum(np.maximum(dx, dy), 0) + np.sqrt(np.maximum(dx, 0) ** 2 + np.maximum(dy, 0) ** 2)


# shell: a hollow ball, wall 0.03 thick, cut open by the plane y = 0.5 (GLSL_SOURCES["shell"]).
def np_shell(x, y, z):
    ball = np.abs(np.sqrt(x * x + y * y + z * z) - np.float32(0.7)) - np.float32(0.015)
    return np.maximum(ball, y - np.float32(0.5))


def glsl_matrix():
    return ", ".join(f"{TILT.T[row, col]:.9e}" for col in range(3) for row in range(3))  # mat3 takes columns


ROTATED_BOX = (f"float sdf(vec3 p) {{ vec3 q = abs(mat3({glsl_matrix()}) * p) - vec3(0.55, 0.4, 0.3); "
               "return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }")
ROTATED_CYLINDER = (f"float sdf(vec3 p) {{ vec3 q = mat3({glsl_matrix()}) * p; "
                    "vec2 d = vec2(length(q.xz) - 0.45, abs(q.y) - 0.6); "
                    "return min(max(d.x, d.y), 0.0) + length(max(d, 0.0)); }")
SHELL = "float sdf(vec3 p) { return max(abs(length(p) - 0.7) - 0.015, p.y - 0.5); }"
GLSL_SOURCES = {"rotated-box": ROTATED_BOX, "rotated-cylinder": ROTATED_CYLINDER, "shell": SHELL}


# --- shaders/lib/primitives.glsl and dataset/lib/modelling.glsl, the pieces the dataset SDFs below call ------------

def sd_box(px, py, pz, hx, hy, hz):
    """sdBox: length(max(q, 0)) + min(max(q.x, max(q.y, q.z)), 0)."""
    qx, qy, qz = np.abs(px) - F(hx), np.abs(py) - F(hy), np.abs(pz) - F(hz)
    return (length3(np.maximum(qx, ZERO), np.maximum(qy, ZERO), np.maximum(qz, ZERO))
            + np.minimum(np.maximum(qx, np.maximum(qy, qz)), ZERO))


def sd_round_box(px, py, pz, hx, hy, hz, r):
    """sdRoundBox: sdBox(p, halfSize - radius) - radius."""
    r = F(r)
    return sd_box(px, py, pz, F(hx) - r, F(hy) - r, F(hz) - r) - r


def sd_cylinder(px, py, pz, radius, half_height):
    """sdCylinder: capped, along y."""
    dx = np.abs(length2(px, pz)) - F(radius)
    dy = np.abs(py) - F(half_height)
    return np.minimum(np.maximum(dx, dy), ZERO) + length2(np.maximum(dx, ZERO), np.maximum(dy, ZERO))


def sd_torus(px, py, pz, major, minor):
    """sdTorus: in the xz plane."""
    return length2(length2(px, pz) - F(major), py) - F(minor)


def op_smooth_union(a, b, k):
    """opSmoothUnion (smoothMin): mix(b, a, h) - k h (1 - h)."""
    k = F(k)
    h = clamp(HALF + HALF * (b - a) / k, 0.0, 1.0)
    return mix(b, a, h) - k * h * (ONE - h)


def sd_segment2(px, py, ax, ay, bx, by):
    pax, pay = px - F(ax), py - F(ay)
    bax, bay = F(bx) - F(ax), F(by) - F(ay)
    h = clamp((pax * bax + pay * bay) / (bax * bax + bay * bay), 0.0, 1.0)
    return length2(pax - bax * h, pay - bay * h)


def sd_trapezoid2(qx, qy, r0, r1, h):
    """sdTrapezoid2: radius r0 at y = -h, r1 at y = +h; exact 2D distance, negative inside."""
    r0, r1, h = F(r0), F(r1), F(h)
    d = np.minimum(sd_segment2(qx, qy, ZERO, -h, r0, -h), sd_segment2(qx, qy, ZERO, h, r1, h))
    d = np.minimum(d, sd_segment2(qx, qy, r0, -h, r1, h))
    t = clamp((qy + h) / (TWO * h), 0.0, 1.0)
    inside = (np.abs(qy) <= h) & (qx <= mix(r0, r1, t))
    return np.where(inside, -d, d)


def sd_frustum(px, py, pz, r0, r1, h):
    return sd_trapezoid2(length2(px, pz), py, r0, r1, h)


def round_cone_profile(x, y, length, ra, rb):
    """roundConeProfile for a cone with len > 1e-5 and |s| < 1 (the branches the dataset's constants take)."""
    ra, rb = F(ra), F(rb)
    s = (ra - rb) / length
    assert length >= F(1e-5) and abs(s) < 1.0, "round cone: a degenerate profile is not written out"
    c = np.sqrt(ONE - s * s)
    k = -x * s + y * c
    return np.where(k < ZERO, length2(x, y) - ra,
                    np.where(k > length * c, length2(x, y - length) - rb, x * c + y * s - ra))


def sd_round_cone(px, py, pz, a, b, ra, rb):
    """sdRoundCone: the hull of spheres (ra at a, rb at b)."""
    a, b = np.asarray(a, F), np.asarray(b, F)
    ba = b - a
    length = np.sqrt(ba[0] * ba[0] + ba[1] * ba[1] + ba[2] * ba[2])
    axis = ba / length
    pax, pay, paz = px - a[0], py - a[1], pz - a[2]
    y = pax * axis[0] + pay * axis[1] + paz * axis[2]
    x = length3(pax - axis[0] * y, pay - axis[1] * y, paz - axis[2] * y)
    return round_cone_profile(x, y, length, ra, rb)


# --- Dataset SDFs -------------------------------------------------------------------------------------------------

# capsule: upright capsule, segment y in [-0.56, 0.56], radius 0.36 (dataset/Geometry/Capsule.glsl).
def capsule(x, y, z):
    half_length, radius = F(0.56), F(0.36)
    dy = y - np.minimum(np.maximum(y, -half_length), half_length)
    return length3(x, dy, z) - radius


# hexagonalprism: upright regular hexagonal prism, apothem 0.78, half height 0.62 (dataset/Geometry/HexagonalPrism.glsl).
def hexagonalprism(x, y, z):
    apothem, half_height = F(0.78), F(0.62)
    half_side = apothem * (F(0.45033) / F(0.78))
    qx, qy = np.abs(x), np.abs(z)
    for mx, my in ((F(0.8660254), F(-0.5)), (F(0.5), F(-0.8660254))):  # mirror60, then mirror30
        t = TWO * np.minimum(qx * mx + qy * my, ZERO)
        qx, qy = qx - t * mx, qy - t * my
    hexagon = length2(qx - apothem, qy - clamp(qy, 0.0, half_side)) * np.sign(qx - apothem)
    wx, wy = hexagon, np.abs(y) - half_height
    return np.minimum(np.maximum(wx, wy), ZERO) + length2(np.maximum(wx, ZERO), np.maximum(wy, ZERO))


# anvil: a blacksmith's anvil, horn towards +x (dataset/Manufactured/Anvil.glsl, with dataset/lib/modelling.glsl
# and shaders/lib/primitives.glsl).
def anvil(x, y, z):
    face = sd_round_box(x - F(-0.15), y - F(0.32), z, 0.5, 0.12, 0.2, 0.02)
    hardy = sd_box(x - F(-0.5), y - F(0.32), z, 0.04, 0.2, 0.04)
    pritchel = sd_cylinder(x - F(-0.36), y - F(0.32), z, 0.025, 0.2)
    face = np.maximum(face, -np.minimum(hardy, pritchel))
    table = sd_round_box(x - F(0.4), y - F(0.28), z, 0.08, 0.08, 0.14, 0.02)
    horn = sd_round_cone(x, y, z, (0.42, 0.26, 0.0), (0.9, 0.3, 0.0), 0.14, 0.02)
    horn = np.maximum(horn, y - F(0.35))
    top = np.minimum(np.minimum(face, table), horn)
    waist = sd_box(x - F(-0.12), y - F(-0.05), z, 0.16, 0.25, 0.09)
    bx, by = x - F(-0.12), y - F(-0.45)
    base = sd_frustum(bx, by, z, 0.42, 0.22, 0.12)
    base = np.maximum(base, sd_box(bx, by, z, 0.42, 0.12, 0.3))
    ny = y - F(-0.58)
    notch = np.minimum(sd_box(bx, ny, z, 0.5, 0.06, 0.12), sd_box(bx, ny, z, 0.2, 0.06, 0.5))
    base = np.maximum(base, -notch)
    body = op_smooth_union(waist, base, 0.16)
    return op_smooth_union(body, top, 0.14)


# mug: a coffee mug with its handle towards +x, coffee level 0.35, handle thickness 0.07 (the uniforms' defaults)
# (dataset/Manufactured/Mug.glsl, with dataset/lib/modelling.glsl and shaders/lib/primitives.glsl).
def mug(x, y, z, coffee_level=0.35, handle_thickness=0.07):
    qx, qy, qz = x - F(-0.15), y - F(-0.05), z
    outer = sd_cylinder(qx, qy, qz, 0.5, 0.55) - F(0.04)
    inner = sd_cylinder(qx, qy - F(0.2), qz, 0.44, 0.55) - F(0.02)
    cup = np.maximum(outer, -inner)
    coffee = sd_cylinder(qx, qy - F(coffee_level), qz, 0.45, 0.02)
    cup = np.minimum(cup, coffee)
    hx, hy, hz = qx - F(0.5), qy - F(0.02), qz
    handle = sd_torus(hx, hz, hy, 0.27, handle_thickness)  # sdTorusXY(h) = sdTorus(h.xzy)
    handle = np.maximum(handle, F(-0.1) - hx)
    return op_smooth_union(cup, handle, 0.05)


def bar_distance(u, v, half_width):
    """MengerSponge's barDistance: an endless bar of square section across the (u, v) plane."""
    ou, ov = np.abs(u) - half_width, np.abs(v) - half_width
    return length2(np.maximum(ou, ZERO), np.maximum(ov, ZERO)) + np.minimum(np.maximum(ou, ov), ZERO)


# mengersponge: Menger sponge of half size 0.78, four levels (dataset/Fractal/MengerSponge.glsl).
def mengersponge(x, y, z):
    half_size = F(0.78)
    qx, qy, qz = x / half_size, y / half_size, z / half_size
    ox, oy, oz = np.abs(qx) - ONE, np.abs(qy) - ONE, np.abs(qz) - ONE
    solid = (length3(np.maximum(ox, ZERO), np.maximum(oy, ZERO), np.maximum(oz, ZERO))
             + np.minimum(np.maximum(ox, np.maximum(oy, oz)), ZERO))
    sx, sy, sz = qx + ONE, qy + ONE, qz + ONE
    cell = F(2.0)
    for _ in range(4):
        lx, ly, lz = (glsl_mod(s, cell) - HALF * cell for s in (sx, sy, sz))
        half_width = cell / F(6.0)
        cross = np.minimum(bar_distance(ly, lz, half_width),
                           np.minimum(bar_distance(lx, lz, half_width), bar_distance(lx, ly, half_width)))
        solid = np.maximum(solid, -cross)
        cell = cell / F(3.0)
    return solid * half_size


# sierpinskitetrahedron: Sierpinski tetrahedron, six levels of folding (dataset/Fractal/SierpinskiTetrahedron.glsl).
def sierpinskitetrahedron(x, y, z):
    scale, levels = F(0.66), 6
    ox, oy, oz = F(0.4082483) * scale, F(0.5773503) * scale, F(0.0) * scale
    qx, qy, qz = (x + ox) / scale, (y + oy) / scale, (z + oz) / scale
    frame_x = (F(0.4082483), F(0.4082483), F(-0.8164966))
    frame_y = (F(0.5773503), F(0.5773503), F(0.5773503))
    frame_z = (F(0.7071068), F(-0.7071068), F(0.0))
    zx, zy, zz = full(*(qx * frame_x[i] + qy * frame_y[i] + qz * frame_z[i] for i in range(3)))
    for _ in range(levels):
        flip = zx + zy < ZERO  # z.xy = -z.yx
        zx, zy = np.where(flip, -zy, zx), np.where(flip, -zx, zy)
        flip = zx + zz < ZERO  # z.xz = -z.zx
        zx, zz = np.where(flip, -zz, zx), np.where(flip, -zx, zz)
        flip = zy + zz < ZERO  # z.yz = -z.zy
        zy, zz = np.where(flip, -zz, zy), np.where(flip, -zy, zz)
        zx, zy, zz = TWO * zx - ONE, TWO * zy - ONE, TWO * zz - ONE
    planes = np.maximum(np.maximum(-zx - zy - zz, zx + zy - zz), np.maximum(-zx + zy + zz, zx - zy + zz))
    tetrahedron = (planes - ONE) * F(0.5773503)
    return tetrahedron * scale / F(1 << levels)


# --- Foreign files ------------------------------------------------------------------------------------------------

# hg-arcade: hg_sdf-style arcade, five columns between two slabs with chamfered joins, turned 0.3 rad about y
# (tests/foreign/42_hg_mercury_arcade.glsl, entry `scene`).
def hg_arcade(x, y, z):
    c, s = np.cos(F(0.3)), np.sin(F(0.3))
    px, pz = c * x + s * z, c * z + s * (-x)  # pR(p.xz, 0.3)
    py = y

    def f_box(bx, by, bz, hx, hy, hz):  # fBox: length(max(d, 0)) + vmax(min(d, 0))
        dx, dy, dz = np.abs(bx) - F(hx), np.abs(by) - F(hy), np.abs(bz) - F(hz)
        return (length3(np.maximum(dx, ZERO), np.maximum(dy, ZERO), np.maximum(dz, ZERO))
                + np.maximum(np.maximum(np.minimum(dx, ZERO), np.minimum(dy, ZERO)), np.minimum(dz, ZERO)))

    def chamfer(a, b, r):  # fOpUnionChamfer
        return np.minimum(np.minimum(a, b), (a + b - F(r)) * np.sqrt(HALF))

    floor_slab = f_box(px, py - F(-0.62), pz, 0.92, 0.08, 0.35)
    roof_slab = f_box(px, py - F(0.62), pz, 0.92, 0.08, 0.35)
    spacing = F(0.38)
    qx = px - spacing * np.floor(px / spacing + HALF)  # pMod1(q.x, SPACING)
    columns = length2(qx, pz) - F(0.07)
    columns = np.maximum(columns, np.abs(px) - F(0.86))
    d = chamfer(columns, floor_slab, 0.04)
    d = chamfer(d, roof_slab, 0.04)
    return np.maximum(d, np.abs(py) - F(0.7))


# iq-primitives: IQ's primitives scene: a floor slab, a sphere, round box, torus, capsule, capped cylinder,
# octahedron bound and a box on top, joined by opU (tests/foreign/01_iq_primitives.glsl, entry `map`, its .x).
def iq_primitives(x, y, z):
    def box(px, py, pz, hx, hy, hz):  # sdBox: inside + outside
        dx, dy, dz = np.abs(px) - F(hx), np.abs(py) - F(hy), np.abs(pz) - F(hz)
        return (np.minimum(np.maximum(dx, np.maximum(dy, dz)), ZERO)
                + length3(np.maximum(dx, ZERO), np.maximum(dy, ZERO), np.maximum(dz, ZERO)))

    def round_box(px, py, pz, b, r):  # sdRoundBox with b = vec3(b)
        b, r = F(b), F(r)
        qx, qy, qz = np.abs(px) - b + r, np.abs(py) - b + r, np.abs(pz) - b + r
        return (length3(np.maximum(qx, ZERO), np.maximum(qy, ZERO), np.maximum(qz, ZERO))
                + np.minimum(np.maximum(qx, np.maximum(qy, qz)), ZERO) - r)

    def capsule_ab(px, py, pz, a, b, r):  # sdCapsule
        a, b = np.asarray(a, F), np.asarray(b, F)
        ba = b - a
        pax, pay, paz = px - a[0], py - a[1], pz - a[2]
        h = clamp((pax * ba[0] + pay * ba[1] + paz * ba[2]) / (ba[0] * ba[0] + ba[1] * ba[1] + ba[2] * ba[2]), 0.0, 1.0)
        return length3(pax - ba[0] * h, pay - ba[1] * h, paz - ba[2] * h) - F(r)

    def capped_cylinder(px, py, pz, h, r):  # sdCappedCylinder
        dx, dy = np.abs(length2(px, pz)) - F(r), np.abs(py) - F(h)
        return np.minimum(np.maximum(dx, dy), ZERO) + length2(np.maximum(dx, ZERO), np.maximum(dy, ZERO))

    def octahedron(px, py, pz, s):  # sdOctahedron (the cheap bound)
        return (np.abs(px) + np.abs(py) + np.abs(pz) - F(s)) * F(0.57735027)

    parts = [
        box(x, y - F(-0.62), z, 0.9, 0.04, 0.9),
        length3(x - F(-0.55), y - F(-0.3), z - F(-0.4)) - F(0.2),
        round_box(x, y - F(-0.3), z - F(-0.4), 0.18, 0.05),
        sd_torus(x - F(0.55), y - F(-0.3), z - F(-0.4), 0.17, 0.05),
        capsule_ab(x, y, z, (-0.65, -0.45, 0.3), (-0.45, -0.1, 0.45), 0.07),
        capped_cylinder(x, y - F(-0.3), z - F(0.4), 0.2, 0.15),
        octahedron(x - F(0.55), y - F(-0.3), z - F(0.4), 0.25),
        box(x, y - F(0.35), z, 0.25, 0.08, 0.25),
    ]
    res = F(1e10)
    for d in parts:  # opU keeps the nearer: the minimum of the distances
        res = np.minimum(res, d)
    return res


# jw-csg: Jamie Wong's CSG scene at iTime = 0: a cube rounded by a ball, minus three rods along the axes
# (tests/foreign/43_jw_csg_phong.glsl, entry `sceneSDF`).
def jw_csg(x, y, z):
    def cylinder(px, py, pz, h, r):  # cylinderSDF: capped, along z, length h end to end
        qx, qy = length2(px, py) - F(r), np.abs(pz) - F(0.5) * F(h)
        return np.minimum(np.maximum(qx, qy), ZERO) + length2(np.maximum(qx, ZERO), np.maximum(qy, ZERO))

    # rotateY(iTime / 2) at iTime = 0 is the identity; rotateY(radians(90)) * p = (c x - s z, y, s x + c z).
    angle = F(90.0) * F(np.pi / 180.0)
    c, s = np.cos(angle), np.sin(angle)
    rod_z = cylinder(x, y, z, 1.6, 0.2)
    rod_x = cylinder(c * x - s * z, y, s * x + c * z, 1.6, 0.2)
    rod_y = cylinder(z, x, y, 1.6, 0.2)  # samplePoint.zxy
    cube = sd_box(x, y, z, 0.45, 0.45, 0.45)
    r = F(0.6)
    ball = (length3(x / r, y / r, z / r) - ONE) * r
    rounded = np.maximum(cube, ball)
    rods = np.minimum(rod_z, np.minimum(rod_x, rod_y))
    return np.maximum(rounded, -rods)


# --- The table --------------------------------------------------------------------------------------------------

FIELDS = {
    "sphere": np_sphere,
    "torus": np_torus,
    "capsule": capsule,
    "box": np_box,
    "rotated-box": np_rotated_box,
    "hexagonalprism": hexagonalprism,
    "rotated-cylinder": np_rotated_cylinder,
    "anvil": anvil,
    "hg-arcade": hg_arcade,
    "iq-primitives": iq_primitives,
    "jw-csg": jw_csg,
    "shell": np_shell,
    "mug": mug,
    "mengersponge": mengersponge,
    "sierpinskitetrahedron": sierpinskitetrahedron,
}

# What sdfwb takes for each field: a dataset name, a foreign file's path, or GLSL text.
SDFWB_SOURCES = {name: name for name in FIELDS}
SDFWB_SOURCES.update(GLSL_SOURCES)
SDFWB_SOURCES.update({
    "hg-arcade": os.path.join(FOREIGN, "42_hg_mercury_arcade.glsl"),
    "iq-primitives": os.path.join(FOREIGN, "01_iq_primitives.glsl"),
    "jw-csg": os.path.join(FOREIGN, "43_jw_csg_phong.glsl"),
})
