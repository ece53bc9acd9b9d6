// Texture coordinates (lecture notes on realism, 1.1): where a point of a
// primitive's surface lands in an image, from the primitive's natural
// parametrization in its own frame, so an image moves with its node. u and v
// run from 0 to 1 across the image (left to right, bottom to top); a
// coordinate that goes round the surface wraps, the others stop at the edge.
// Each mapping reads the primitive's own parameter slots (instructions.glsl).
const int MAP_SPHERICAL = 1;  // sphere, ellipsoid: longitude and latitude; s0 = radii
const int MAP_BOX = 2;        // box, round box: each face shows the whole image; s0 = half extents
const int MAP_PLANE = 3;      // plane: tiles of the texture's scale; s0 = (unit normal, tiles per unit)
const int MAP_CYLINDER = 4;   // side once round and once up, caps as discs; s0 = (radius, half height)
const int MAP_CONE = 5;       // side once round, base to apex; base as a disc; s0 = (sin, cos, height)
const int MAP_TORUS = 6;      // once round the axis, once round the tube; s0 = (major, minor radius)
const int MAP_CAPSULE = 7;    // once round the axis, from a's cap to b's; s0 = (a, radius), s1 = (b, 0)

struct TexturePoint {
    real u;
    real v;
    bool wrapU;
    bool wrapV;
};

// A coordinate as the sampler takes it: one that wraps reduced to [0, 1)
// first (so a far tile keeps its texel accurate), then clamped to [0, 1],
// which also turns a NaN into 0 (GLSL leaves int() of a NaN undefined).
SHARED_FN real mapCoordinate(real x, bool wrap) { return clamp(wrap ? fractr(x) : x, real(0), real(1)); }

// The turn about `axisUp` (the primitive's axis, +y unless a capsule's) seen
// from outside: 1/2 faces +z (the front a default camera sees), 0 and 1 meet
// at the back, u grows towards +x.
SHARED_FN real aroundAxis(real x, real z) { return real(0.5) + libraryAtan2(x, z) / (real(2) * PI); }

// A tangent of the plane with unit normal n, horizontal for a wall (so v runs
// up the wall) and +x for a floor (v then runs towards -z, away from a viewer).
SHARED_FN vec3 planeTangent(vec3 n) {
    vec3 up = vec3(real(0), real(1), real(0));
    return normalize3(abs(n.y) < real(0.9) ? cross3(up, n) : cross3(n, vec3(real(0), real(0), real(1))));
}

// The environment's latitude-longitude map (environment.glsl) mirrored in z,
// so the image's centre faces +z instead of -z.
SHARED_FN TexturePoint sphericalPoint(vec3 p, vec3 radii) {
    vec3 d = p / radii;
    MapPoint m = equirectPoint(vec3(d.x, d.y, -d.z));
    return TexturePoint(m.u, m.v, true, false);
}

// The face whose slab the point is furthest out of (ties to x, then y), seen
// from outside with up +y for the side faces, -z for the top, +z for the bottom.
SHARED_FN TexturePoint boxFacePoint(vec3 p, vec3 h) {
    vec3 q = abs(p) / h;
    vec3 f = p / (real(2) * h);
    if (q.x >= q.y && q.x >= q.z) {
        return TexturePoint(p.x > real(0) ? real(0.5) - f.z : real(0.5) + f.z, real(0.5) + f.y, false, false);
    }
    if (q.y >= q.z) {
        return TexturePoint(real(0.5) + f.x, p.y > real(0) ? real(0.5) - f.z : real(0.5) + f.z, false, false);
    }
    return TexturePoint(p.z > real(0) ? real(0.5) + f.x : real(0.5) - f.x, real(0.5) + f.y, false, false);
}

SHARED_FN TexturePoint planePoint(vec3 p, vec3 n, real tilesPerUnit) {
    vec3 t = planeTangent(n);
    vec3 b = cross3(n, t);
    return TexturePoint(dot3(p, t) * tilesPerUnit, dot3(p, b) * tilesPerUnit, true, true);
}

// A cap of radius r seen from outside along +y (top) or -y (bottom).
SHARED_FN TexturePoint discPoint(vec3 p, real r, bool top) {
    real z = p.z / (real(2) * r);
    return TexturePoint(real(0.5) + p.x / (real(2) * r), top ? real(0.5) - z : real(0.5) + z, false, false);
}

SHARED_FN TexturePoint cylinderPoint(vec3 p, real r, real halfHeight) {
    real radial = length2d(vec2(p.x, p.z));
    if (abs(p.y) - halfHeight > radial - r) {
        return discPoint(p, r, p.y > real(0));
    }
    return TexturePoint(aroundAxis(p.x, p.z), (p.y + halfHeight) / (real(2) * halfHeight), true, false);
}

// The apex at the origin, the base at y = -height (primitives.glsl).
SHARED_FN TexturePoint conePoint(vec3 p, real s, real c, real height) {
    real radial = length2d(vec2(p.x, p.z));
    if (-height - p.y > s * radial + c * p.y) {
        return discPoint(p, height * c / s, false);
    }
    return TexturePoint(aroundAxis(p.x, p.z), (p.y + height) / height, true, false);
}

SHARED_FN TexturePoint torusPoint(vec3 p, real major) {
    real radial = length2d(vec2(p.x, p.z));
    return TexturePoint(aroundAxis(p.x, p.z), real(0.5) + libraryAtan2(p.y, radial - major) / (real(2) * PI), true,
                        true);
}

SHARED_FN TexturePoint capsulePoint(vec3 p, vec3 a, vec3 b, real r) {
    vec3 axis = b - a;
    real axisLength = length3(axis);
    vec3 w = axisLength > real(0) ? axis / axisLength : vec3(real(0), real(1), real(0));
    vec3 t = planeTangent(w);
    vec3 s = cross3(w, t);
    vec3 q = p - a;
    real along = dot3(q, w);
    return TexturePoint(aroundAxis(dot3(q, t), -dot3(q, s)), (along + r) / (axisLength + real(2) * r), true, false);
}

SHARED_FN TexturePoint texturePoint(int mapping, vec3 p, vec4 s0, vec4 s1) {
    if (mapping == MAP_SPHERICAL) {
        return sphericalPoint(p, xyz(s0));
    }
    if (mapping == MAP_BOX) {
        return boxFacePoint(p, xyz(s0));
    }
    if (mapping == MAP_PLANE) {
        return planePoint(p, xyz(s0), s0.w);
    }
    if (mapping == MAP_CYLINDER) {
        return cylinderPoint(p, s0.x, s0.y);
    }
    if (mapping == MAP_CONE) {
        return conePoint(p, s0.x, s0.y, s0.z);
    }
    if (mapping == MAP_TORUS) {
        return torusPoint(p, s0.x);
    }
    if (mapping == MAP_CAPSULE) {
        return capsulePoint(p, xyz(s0), xyz(s1), s0.w);
    }
    return TexturePoint(real(0.5), real(0.5), false, false);
}
