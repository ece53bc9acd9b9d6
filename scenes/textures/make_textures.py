#!/usr/bin/env python3
"""Writes the texture images the scenes use, made here from formulas: a
(u, v) test grid, a small planet as a latitude-longitude image, a tiling
brick wall and its height map. Standard library only; PNGs written by the
environments' script.

    python3 scenes/textures/make_textures.py   # rewrites the PNGs beside it

(u, v) follow docs/scene-format.md ("Image textures"): u from the image's
left edge to its right, v from its bottom edge to its top.
"""
import importlib.util
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    "make_environments", os.path.join(HERE, "..", "environments", "make_environments.py"))
_environments = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_environments)


def write_png(name, width, height, pixel, colour=True):
    _environments.HERE = HERE
    _environments.write_png(name, width, height, pixel, colour)


def uv_grid(x, y, size=256, cells=8):
    """Hue by (u, v), alternate cells darker, dark cell borders, a white
    corner cell at (0, 0) so the image's orientation shows."""
    u, v = (x + 0.5) / size, 1 - (y + 0.5) / size
    cu, cv = int(u * cells), int(v * cells)
    fu, fv = u * cells - cu, v * cells - cv
    if min(fu, fv, 1 - fu, 1 - fv) < 0.04:
        return (0.02, 0.02, 0.02)
    if cu == 0 and cv == 0:
        return (0.9, 0.9, 0.9)
    shade = 0.85 if (cu + cv) % 2 == 0 else 0.45
    return (shade * (0.2 + 0.8 * u), shade * (0.2 + 0.8 * v), shade * 0.35)


def lattice(ix, iy, seed):
    n = (ix * 374761393 + iy * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    n = (n ^ (n >> 13)) * 1274126177 & 0xFFFFFFFF
    return (n ^ (n >> 16)) / 0xFFFFFFFF


def value_noise(x, y, period, seed):
    """Smooth noise that tiles every `period` lattice cells in x."""
    ix, iy = math.floor(x), math.floor(y)
    fx, fy = x - ix, y - iy
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    def h(a, b):
        return lattice(a % period, b, seed)
    top = h(ix, iy) + (h(ix + 1, iy) - h(ix, iy)) * sx
    bottom = h(ix, iy + 1) + (h(ix + 1, iy + 1) - h(ix, iy + 1)) * sx
    return top + (bottom - top) * sy


def planet(x, y, width=512, height=256):
    """Oceans, land by latitude (green, desert, tundra) and ice caps; the
    noise tiles round the globe, so the seam at u = 0 does not show."""
    u, v = (x + 0.5) / width, 1 - (y + 0.5) / height
    latitude = abs(v - 0.5) * 2
    e = sum(value_noise(u * 8 * 2 ** o, v * 4 * 2 ** o, 8 * 2 ** o, o) / 2 ** o for o in range(4)) / 1.875
    if latitude > 0.86 - 0.1 * e:
        return (0.9, 0.92, 0.95)
    if e < 0.52:
        depth = (0.52 - e) / 0.52
        return (0.02, 0.08 + 0.1 * (1 - depth), 0.3 + 0.2 * (1 - depth))
    if latitude > 0.72 - 0.15 * e:
        return (0.35, 0.38, 0.3)
    dry = value_noise(u * 12, v * 6, 12, 9)
    if dry > 0.55 and latitude < 0.5:
        return (0.55, 0.42, 0.2)
    return (0.08, 0.3 + 0.3 * (e - 0.52), 0.06)


def bricks(x, y, size=128):
    """Two courses of bricks per image, offset by half a brick, so the image tiles."""
    u, v = x / size, y / size
    course = int(v * 4)
    shift = 0.25 if course % 2 else 0.0
    bu = (u * 2 + shift) % 1.0
    bv = (v * 4) % 1.0
    if bu < 0.04 or bv < 0.08:
        return (0.5, 0.48, 0.45)
    tone = 0.8 + 0.2 * lattice(int(u * 2 + shift), course, 7)
    return (0.45 * tone, 0.14 * tone, 0.08 * tone)


def bricks_height(x, y, size=128):
    """The bricks' height map, laid out as bricks(): mortar at 0, brick faces
    at 1 with rounded edges, a little unevenness on each face."""
    u, v = x / size, y / size
    course = int(v * 4)
    shift = 0.25 if course % 2 else 0.0
    bu = (u * 2 + shift) % 1.0
    bv = (v * 4) % 1.0
    # distance into the brick from its mortar lines, in bricks' half-heights
    inside = min((bu - 0.04) / 0.08, (1 - bu) / 0.08, (bv - 0.08) / 0.16, (1 - bv) / 0.16)
    if inside <= 0:
        return (0.0, 0.0, 0.0)
    edge = min(inside, 1.0)
    h = edge * edge * (3 - 2 * edge) * (0.9 + 0.1 * value_noise(u * 16, v * 16, 16, 3))
    return (h, h, h)


if __name__ == "__main__":
    write_png("uv_grid.png", 256, 256, uv_grid)
    write_png("planet.png", 512, 256, planet)
    write_png("bricks.png", 128, 128, bricks)
    write_png("bricks_height.png", 128, 128, bricks_height, colour=False)  # heights are data
