#!/usr/bin/env python3
"""Writes the environment images the scenes use, made here from formulas:
an outdoor sky as a latitude-longitude map and as a mirror-ball (sphere) map,
and a studio room as the six faces of a box map. Standard library only.

    python3 scenes/environments/make_environments.py   # rewrites the PNGs beside it

Directions follow docs/scene-format.md ("Environment maps"): the
latitude-longitude image's centre looks along -z and u grows towards +x; the
sphere map is a mirror ball seen from +z; each box face is seen from the
centre with up +y (the top face: up +z, the bottom face: up -z).
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(name, width, height, pixel, colour=True):
    """pixel(x, y) -> linear (r, g, b); y = 0 is the top row; stored as sRGB 8-bit,
    or with colour=False (data such as heights) as the fraction of 255 itself."""
    def encode(c):
        c = max(0.0, min(1.0, c))
        s = (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055) if colour else c
        return int(round(s * 255))
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            rows.extend(encode(c) for c in pixel(x, y))
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(png)


EDGE = 0.003  # half the width of the hills' antialiased edge, in units of direction y


def smooth(a, b, x):
    t = min(1.0, max(0.0, (x - a) / (b - a)))
    return t * t * (3 - 2 * t)


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


SUN = (0.55, 0.42, -0.72)  # towards the sun, front right and up
SUN = tuple(c / math.sqrt(sum(v * v for v in SUN)) for c in SUN)


def sky(d):
    """Radiance arriving from direction d: sky, sun, distant hills, a ground of fields."""
    x, y, z = d
    azimuth = math.atan2(x, -z)
    hills = 0.06 + 0.035 * math.sin(3 * azimuth) + 0.02 * math.sin(7 * azimuth + 1.3)
    if y > 0.0:
        t = min(1.0, max(0.0, y - hills) / 0.9)
        air = mix((0.75, 0.82, 0.9), (0.12, 0.3, 0.75), t ** 0.7)
        cos_sun = x * SUN[0] + y * SUN[1] + z * SUN[2]
        glow = max(0.0, cos_sun) ** 64 * 0.9
        air = tuple(c + glow * w for c, w in zip(air, (1.0, 0.85, 0.6)))
        air = mix(air, (1.0, 0.97, 0.9), smooth(0.99925, 0.99935, cos_sun))
        shade = 0.6 + 0.4 * min(1.0, y / hills)
        hill = (0.16 * shade, 0.3 * shade, 0.14 * shade)
        # the hills' edge antialiased over about a texel, so it does not step when magnified
        return mix(hill, air, smooth(-EDGE, EDGE, y - hills))
    # fields on the ground plane, fading into haze at the horizon
    u, v = x / max(-y, 1e-3), z / max(-y, 1e-3)
    field = (math.floor(u * 0.5) + math.floor(v * 0.5)) % 2
    ground = (0.35, 0.3, 0.12) if field else (0.2, 0.36, 0.12)
    return mix((0.55, 0.6, 0.6), ground, min(1.0, -y * 6))


def equirect(width, height):
    def pixel(px, py):
        u = (px + 0.5) / width
        v = 1 - (py + 0.5) / height
        lon = (u - 0.5) * 2 * math.pi
        lat = (v - 0.5) * math.pi
        return sky((math.cos(lat) * math.sin(lon), math.sin(lat), -math.cos(lat) * math.cos(lon)))
    write_png("sky_equirect.png", width, height, pixel)


def sphere_map(side):
    def pixel(px, py):
        nx = 2 * (px + 0.5) / side - 1
        ny = 1 - 2 * (py + 0.5) / side
        r2 = nx * nx + ny * ny
        if r2 > 1:  # outside the ball: its rim's colour, so filtering at the rim stays clean
            nx, ny, r2 = nx / math.sqrt(r2), ny / math.sqrt(r2), 1.0
        nz = math.sqrt(1 - r2)
        # reflect the view direction (0, 0, -1) about n: d = v - 2 (v.n) n
        return sky((2 * nz * nx, 2 * nz * ny, -1 + 2 * nz * nz))
    write_png("sky_sphere.png", side, side, pixel)


def studio(d):
    """A grey room with a tiled floor, a warm wall, a cool wall and a window."""
    x, y, z = d
    m = max(abs(x), abs(y), abs(z))
    x, y, z = x / m, y / m, z / m
    tiles = lambda a, b: 0.85 + 0.15 * ((math.floor(a * 4) + math.floor(b * 4)) % 2)
    if y <= -0.999:
        return tuple(c * tiles(x, z) for c in (0.35, 0.33, 0.3))
    if y >= 0.999:
        lamp = 3.0 if abs(x) < 0.25 and abs(z) < 0.25 else 0.0
        return (0.6 + lamp, 0.6 + lamp, 0.62 + lamp)
    if x >= 0.999:
        window = abs(z) < 0.5 and -0.1 < y < 0.7
        return (1.6, 1.7, 1.9) if window else (0.55, 0.55, 0.58)
    if x <= -0.999:
        return tuple(c * tiles(z, y) for c in (0.7, 0.35, 0.15))
    if z >= 0.999:
        return tuple(c * tiles(x, y) for c in (0.15, 0.35, 0.6))
    stripe = 1.0 if (math.floor((x + 1) * 6) % 2) else 0.8
    return (0.5 * stripe, 0.5 * stripe, 0.48 * stripe)


def box_faces(side):
    # (name, forward, right, up) of each face, as docs/scene-format.md has them
    faces = [("px", (1, 0, 0), (0, 0, 1), (0, 1, 0)), ("nx", (-1, 0, 0), (0, 0, -1), (0, 1, 0)),
             ("py", (0, 1, 0), (1, 0, 0), (0, 0, 1)), ("ny", (0, -1, 0), (1, 0, 0), (0, 0, -1)),
             ("pz", (0, 0, 1), (-1, 0, 0), (0, 1, 0)), ("nz", (0, 0, -1), (1, 0, 0), (0, 1, 0))]
    for name, f, r, u in faces:
        def pixel(px, py, f=f, r=r, u=u):
            a = 2 * (px + 0.5) / side - 1
            b = 1 - 2 * (py + 0.5) / side
            return studio(tuple(f[i] + a * r[i] + b * u[i] for i in range(3)))
        write_png("studio_" + name + ".png", side, side, pixel)


if __name__ == "__main__":
    equirect(1024, 512)
    sphere_map(512)
    box_faces(128)
