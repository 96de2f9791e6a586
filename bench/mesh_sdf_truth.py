"""Ground truth for a triangle mesh's signed distance that shares no code with sdfwb: the float64
distance to the nearest triangle by brute force (every triangle, Ericson's closest-point regions in
NumPy) and the exact generalized winding number (every triangle's solid angle, van Oosterom and
Strackee). Used by bench/bench_mesh_sdf.py on a subset of its points."""
import numpy as np


def closest_distances(vertices, faces, points):
    """Unsigned float64 distance from each point to the nearest triangle (brute force)."""
    a, b, c = (vertices[faces[:, k]].astype(np.float64) for k in range(3))
    ab, ac = b - a, c - a
    out = np.empty(len(points))
    for i, p in enumerate(points.astype(np.float64)):
        ap, bp, cp = p - a, p - b, p - c
        d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
        d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
        d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
        va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
        with np.errstate(divide="ignore", invalid="ignore"):
            total = va + vb + vc
            q = a + ab * (vb / total)[:, None] + ac * (vc / total)[:, None]  # the face
            regions = [
                (d1 <= 0) & (d2 <= 0), (d3 >= 0) & (d4 <= d3), (vc <= 0) & (d1 >= 0) & (d3 <= 0),
                (d6 >= 0) & (d5 <= d6), (vb <= 0) & (d2 >= 0) & (d6 <= 0),
                (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)]
            values = [a, b, a + ab * (d1 / (d1 - d3))[:, None], c, a + ac * (d2 / (d2 - d6))[:, None],
                      b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))[:, None]]
        taken = np.zeros(len(a), bool)
        for region, value in zip(regions, values):
            pick = region & ~taken
            q[pick] = value[pick]
            taken |= region
        # Degenerate triangles (no region, zero area): the nearest of their edges.
        bad = ~taken & ~(total > 0)
        if bad.any():
            best = np.full(bad.sum(), np.inf)
            for s, e in ((a, b), (b, c), (c, a)):
                d = e[bad] - s[bad]
                t = np.clip(np.einsum("ij,ij->i", p - s[bad], d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
                r = s[bad] + d * t[:, None]
                best = np.minimum(best, np.linalg.norm(p - r, axis=1))
            out[i] = min(np.min(np.linalg.norm(p - q[~bad], axis=1), initial=np.inf), best.min())
        else:
            out[i] = np.min(np.linalg.norm(p - q, axis=1))
    return out


def winding_numbers(vertices, faces, points):
    """Exact generalized winding number at each point (sum of every triangle's solid angle / 4 pi)."""
    a, b, c = (vertices[faces[:, k]].astype(np.float64) for k in range(3))
    out = np.empty(len(points))
    for i, p in enumerate(points.astype(np.float64)):
        A, B, C = a - p, b - p, c - p
        la, lb, lc = (np.linalg.norm(X, axis=1) for X in (A, B, C))
        det = np.einsum("ij,ij->i", A, np.cross(B, C))
        den = la * lb * lc + np.einsum("ij,ij->i", A, B) * lc + np.einsum("ij,ij->i", B, C) * la + \
            np.einsum("ij,ij->i", C, A) * lb
        out[i] = np.sum(2 * np.arctan2(det, den)) / (4 * np.pi)
    return out
