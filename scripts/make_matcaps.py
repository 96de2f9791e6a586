#!/usr/bin/env python3
"""Generates the matcaps sdfwb ships (resources/matcaps/*.png): lit spheres computed here from a
few analytic lights, so no third-party image is involved. Rerun after changing a material:

    /usr/bin/python3 scripts/make_matcaps.py
"""
import os

import matplotlib.image
import numpy as np

SIZE = 256
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "matcaps")


def sphere_normals(size):
    """View-space normals of a unit sphere filling the image; background gets the rim normal."""
    v, u = np.mgrid[0:size, 0:size].astype(np.float64)
    x = (u + 0.5) / size * 2 - 1
    y = 1 - (v + 0.5) / size * 2
    r2 = np.minimum(x * x + y * y, 1.0)
    z = np.sqrt(1.0 - r2)
    n = np.stack([x, y, z], axis=-1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def normalize(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v)


def material(n, base, lights, ambient, specular, shininess, rim, reflection=None):
    view = np.array([0.0, 0.0, 1.0])
    color = np.zeros(n.shape)
    color += np.asarray(ambient) * base
    for direction, light in lights:
        l = normalize(direction)
        diffuse = np.clip(n @ l, 0, None)[..., None]
        h = normalize(l + view)
        spec = np.clip(n @ h, 0, None)[..., None] ** shininess
        color += diffuse * base * light + specular * spec * light
    facing = np.clip(n[..., 2], 0, 1)[..., None]
    color += rim * (1 - facing) ** 3
    if reflection is not None:
        # A fake environment: sky above, ground below, a horizon band, reflected about the normal.
        r = 2 * n[..., 2:3] * n - view
        sky = np.array(reflection[0])
        ground = np.array(reflection[1])
        t = np.clip(r[..., 1:2] * 0.5 + 0.5, 0, 1)
        env = ground * (1 - t) + sky * t
        env += 0.6 * np.exp(-((r[..., 1:2] - 0.05) ** 2) / 0.004)
        color = color * 0.35 + env * 0.65
    return np.clip(color, 0, 1)


def save(name, rgb):
    os.makedirs(OUT, exist_ok=True)
    matplotlib.image.imsave(os.path.join(OUT, name + ".png"), (rgb * 255 + 0.5).astype(np.uint8))


n = sphere_normals(SIZE)
key, fill, back = ([-0.5, 0.7, 0.6], [1.0, 0.95, 0.9]), ([0.7, -0.2, 0.5], [0.35, 0.4, 0.5]), ([0.0, 0.3, -1.0], [0.5, 0.5, 0.55])
save("clay", material(n, np.array([0.78, 0.68, 0.6]), [key, fill, back], [0.18, 0.16, 0.15], 0.12, 12, 0.15))
save("wax", material(n, np.array([0.75, 0.18, 0.14]), [key, fill], [0.2, 0.05, 0.04], 0.55, 40, 0.35))
save("jade", material(n, np.array([0.3, 0.62, 0.45]), [key, fill, back], [0.06, 0.16, 0.1], 0.7, 60, 0.3))
save("chrome", material(n, np.array([0.55, 0.56, 0.6]), [key, fill], [0.05, 0.05, 0.05], 1.0, 120, 0.1,
                        reflection=([0.75, 0.82, 0.95], [0.18, 0.15, 0.12])))
print("wrote", ", ".join(sorted(os.listdir(OUT))), "to", os.path.normpath(OUT))
