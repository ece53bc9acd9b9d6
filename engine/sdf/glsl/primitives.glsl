// Signed distance primitives (thesis, section 1; exactness labels in docs/scene-format.md).
// Every primitive is centred at the origin of its own frame.

// exact
SHARED_FN real sdSphere(vec3 p, real radius) { return length3(p) - radius; }

// exact
SHARED_FN real sdBox(vec3 p, vec3 halfExtents) {
    vec3 q = abs(p) - halfExtents;
    return length3(max(q, vec3(real(0)))) + min(max(q.x, max(q.y, q.z)), real(0));
}

// exact; halfExtents include the rounding radius
SHARED_FN real sdRoundBox(vec3 p, vec3 halfExtents, real radius) {
    return sdBox(p, halfExtents - vec3(radius)) - radius;
}

// exact; unitNormal has length 1, the plane is {p : dot(p, n) = offset}
SHARED_FN real sdPlane(vec3 p, vec3 unitNormal, real offset) { return dot3(p, unitNormal) - offset; }

// exact; around the y axis
SHARED_FN real sdTorus(vec3 p, real majorRadius, real minorRadius) {
    vec2 q = vec2(length2d(vec2(p.x, p.z)) - majorRadius, p.y);
    return length2d(q) - minorRadius;
}

// bound (thesis, Example 1.2): apex at the origin, opening downwards along -y to
// height h; sinCos = (sin(angle), cos(angle)) of the angle between the side and the
// base plane (the half-angle at the apex is 90 degrees minus it), computed by the host.
SHARED_FN real sdCone(vec3 p, vec2 sinCos, real height) {
    real radial = length2d(vec2(p.x, p.z));
    return max(dot2(sinCos, vec2(radial, p.y)), -height - p.y);
}

// bound: outside, the thesis's k0 * (k0 - 1) / k1 (Example 1.2). Inside that
// formula is no bound (its Lipschitz constant reaches ~7 near the centre), so
// there (k0 - 1) * min radius, which is 1-Lipschitz and meets it at the surface.
SHARED_FN real sdEllipsoid(vec3 p, vec3 radii) {
    real k0 = length3(p / radii);
    if (k0 < real(1)) {
        return (k0 - real(1)) * min(radii.x, min(radii.y, radii.z));
    }
    real k1 = length3(p / (radii * radii));
    return k0 * (k0 - real(1)) / k1;
}

// exact; capped, along the y axis
SHARED_FN real sdCylinder(vec3 p, real radius, real halfHeight) {
    vec2 d = abs(vec2(length2d(vec2(p.x, p.z)), p.y)) - vec2(radius, halfHeight);
    return min(max(d.x, d.y), real(0)) + length2d(max(d, vec2(real(0))));
}

// exact; segment from a to b
SHARED_FN real sdCapsule(vec3 p, vec3 a, vec3 b, real radius) {
    vec3 pa = p - a;
    vec3 ba = b - a;
    real baLengthSquared = dot3(ba, ba);
    real h = real(0);
    if (baLengthSquared > real(0)) {
        h = saturate(dot3(pa, ba) / baLengthSquared);
    }
    return length3(pa - ba * h) - radius;
}
