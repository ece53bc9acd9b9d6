#!/usr/bin/env python3
"""A model of docs/open-cases/soft_shadow_banding.json (issue 14, class 5).

Shadow rays from a grid of points on the open box's floor, sphere traced
towards the light, with the penumbra factor min(k d / t) taken three ways:
the tracer's meeting-circle estimate on the difference's field (a bound), the
same from the concave hull of all samples' f^2 - t^2 (the most a
sample-based estimate can claim, see docs/numerical-stability.md), and the
tracer's estimate on the intended scene's exact field (five boxes). Prints
the range and mean of each over the floor points the exact field lights
fully. Plain Python, no dependencies: python3 penumbra_bound_model.py
"""
import math

K = 8.0
LIGHT = (0.45, 0.8, 0.3)
LIGHT = tuple(v / math.sqrt(sum(w * w for w in LIGHT)) for v in LIGHT)


def box(p, centre, half):
    q = [abs(p[i] - centre[i]) - half[i] for i in range(3)]
    return math.sqrt(sum(max(v, 0.0) ** 2 for v in q)) + min(max(q), 0.0)


def bound_field(p):  # box minus box, as the open case builds it
    outer = box(p, (0, 0.6, 0), (1, 0.6, 1))
    cutter = box(p, (0, 0.75, 0), (0.85, 0.6, 0.85))
    return min(max(outer, -cutter), p[1])


def exact_field(p):  # the intended version: floor slab and four walls
    walls = [box(p, (0, 0.075, 0), (1, 0.075, 1)),
             box(p, (0.925, 0.6, 0), (0.075, 0.6, 1)), box(p, (-0.925, 0.6, 0), (0.075, 0.6, 1)),
             box(p, (0, 0.6, 0.925), (1, 0.6, 0.075)), box(p, (0, 0.6, -0.925), (1, 0.6, 0.075))]
    return min(min(walls), p[1])


def g(sample):
    t, h = sample
    return h * h - t * t


def closest_between(a, b):
    """Lower bound of the distance between two samples from the chord of f^2 - t^2."""
    slope = (g(b) - g(a)) / (b[0] - a[0])
    t = min(max(-slope / 2, a[0]), b[0])
    return t, math.sqrt(max(t * t + g(a) + slope * (t - a[0]), 0.0))


def penumbra(origin, field, use_hull):
    samples, t = [], 0.01
    while t < 20:
        h = field(tuple(origin[i] + LIGHT[i] * t for i in range(3)))
        if h < 1e-4:
            return 0.0
        samples.append((t, h))
        t += h
    chain = samples
    if use_hull:  # upper concave hull of (t, f^2 - t^2)
        chain = []
        for s in samples:
            chain.append(s)
            while len(chain) >= 3:
                a, b, c = chain[-3:]
                if g(b) < g(a) + (g(c) - g(a)) * (b[0] - a[0]) / (c[0] - a[0]):
                    del chain[-2]
                else:
                    break
    result = min(1.0, min(K * h / t for t, h in samples))
    for a, b in zip(chain, chain[1:]):
        t, d = closest_between(a, b)
        result = min(result, K * d / t)
    return max(result, 0.0)


def main():
    today, hull = [], []
    for xi in range(-8, 9):
        for zi in range(-8, 9):
            origin = (xi * 0.1, 0.15, zi * 0.1)
            if penumbra(origin, exact_field, False) < 0.999:
                continue
            today.append(penumbra(origin, bound_field, False))
            hull.append(penumbra(origin, bound_field, True))
    for name, values in (("meeting circle", today), ("concave hull", hull)):
        print(f"{name}: {len(values)} fully lit points, {min(values):.2f} to {max(values):.2f}, "
              f"mean {sum(values) / len(values):.2f} (exact field: 1.00)")


if __name__ == "__main__":
    main()
