#!/usr/bin/env python3
"""Draws sdfwb.png (256x256 RGBA), the raster twin of sdfwb.svg, from the same distance field:
d(p) = min(circle, square); orange inside, a white zero contour 3 units wide, then bands every 16
units out to 128, on a rounded tile. 4x4 samples per pixel. NumPy and the standard library only.

    python3 resources/icons/make_png.py resources/icons/sdfwb.png
"""
import struct
import sys
import zlib

import numpy as np

SIZE, SUB = 256, 4
ORANGE, WHITE, LIGHT, DARK, BACK = "#f0923a", "#e8eef4", "#2b4660", "#223850", "#1b2c40"


def rgb(hex_colour):
    return np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)], dtype=np.float64)


def box(x, y, cx, cy, half):
    qx, qy = np.abs(x - cx) - half, np.abs(y - cy) - half
    outside = np.hypot(np.maximum(qx, 0), np.maximum(qy, 0))
    return outside + np.minimum(np.maximum(qx, qy), 0)


def rounded_box(x, y, cx, cy, half, radius):
    return box(x, y, cx, cy, half - radius) - radius


def write_png(path, rgba):
    height, width, _ = rgba.shape
    raw = b"".join(b"\x00" + rgba[row].tobytes() for row in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        out.write(chunk(b"IEND", b""))


def main():
    offsets = (np.arange(SIZE * SUB) + 0.5) / SUB
    x, y = np.meshgrid(offsets, offsets)
    d = np.minimum(np.hypot(x - 150, y - 104) - 50, box(x, y, 100, 156, 42))
    band = np.ceil(d / 16)
    colour = np.where((band % 2 == 1)[..., None], rgb(LIGHT), rgb(DARK))
    colour = np.where((band > 8)[..., None], rgb(BACK), colour)
    colour = np.where((d <= 3)[..., None], rgb(WHITE), colour)
    colour = np.where((d <= 0)[..., None], rgb(ORANGE), colour)
    inside_tile = (rounded_box(x, y, 128, 128, 120, 40) <= 0).astype(np.float64)
    # Average the samples of each pixel (colour weighted by coverage, so the edge does not darken).
    def pixels(values):
        return values.reshape(SIZE, SUB, SIZE, SUB, -1).mean(axis=(1, 3))
    coverage = pixels(inside_tile[..., None])
    premultiplied = pixels(colour * inside_tile[..., None])
    straight = np.where(coverage > 0, premultiplied / np.maximum(coverage, 1e-9), 0)
    rgba = np.concatenate([straight, coverage * 255], axis=-1)
    write_png(sys.argv[1] if len(sys.argv) > 1 else "sdfwb.png", np.clip(np.rint(rgba), 0, 255).astype(np.uint8))


if __name__ == "__main__":
    main()
