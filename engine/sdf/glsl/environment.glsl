// Environment maps (lecture notes on realism, 1.5): the light that rays leaving
// the scene see, by their direction alone, as if it came from infinitely far.
// Each map is one or six square images of side N = 2^n with their mipmaps
// (lecture notes 1.1), stored level after level, rows from the bottom (v up),
// in the backend's texel buffer; environment_lookup.glsl reads them. Here:
// where a direction lands in the images, and how many texels a radian spans.
const int ENVIRONMENT_COLOR = 0;     // the background colour, no image
const int ENVIRONMENT_EQUIRECT = 1;  // one latitude-longitude image
const int ENVIRONMENT_SPHERE = 2;    // one image of a mirror ball seen along -z (the notes' sphere map)
const int ENVIRONMENT_BOX = 3;       // six face images, +x -x +y -y +z -z (the notes' box map)


// A point of a map: which image (a box face, else 0) and where in it, u and v
// in [0, 1] from the image's left and bottom edges.
struct MapPoint {
    int face;
    real u;
    real v;
};

// Latitude and longitude: the image centre looks along -z, u grows towards +x
// (a quarter turn to the right is u = 3/4), v from the nadir (0) to the
// zenith (1).
SHARED_FN MapPoint equirectPoint(vec3 d) {
    real horizontal = sqrt(d.x * d.x + d.z * d.z);
    real u = real(0.5) + libraryAtan2(d.x, -d.z) / (real(2) * PI);
    real v = real(0.5) + libraryAtan2(d.y, horizontal) / PI;
    return MapPoint(0, u, v);
}

// The mirror ball seen orthographically from +z: the ball's point whose normal
// halves the way between the view direction (+z) and d reflects d, so
// n = normalize(d + z) and the image point is (n.x, n.y) on the unit disc.
// d = -z, behind the ball, is its whole rim; it maps to the rim's top.
SHARED_FN MapPoint spherePoint(vec3 d) {
    vec3 h = d + vec3(real(0), real(0), real(1));
    vec3 n = dot3(h, h) > real(0) ? normalize3(h) : vec3(real(0), real(1), real(0));
    return MapPoint(0, real(0.5) + real(0.5) * n.x, real(0.5) + real(0.5) * n.y);
}

// The face of the cube that d points at (its largest component; ties to x,
// then y) and the point on it. Each face is what a viewer at the centre sees
// looking at it with up +y for the side faces, +z for the top and -z for the
// bottom, so the faces meet as in a horizontal cross around -z.
SHARED_FN MapPoint boxPoint(vec3 d) {
    real ax = abs(d.x);
    real ay = abs(d.y);
    real az = abs(d.z);
    if (ax >= ay && ax >= az) {
        real s = real(0.5) / max(ax, real(1e-30));
        return d.x > real(0) ? MapPoint(0, real(0.5) + d.z * s, real(0.5) + d.y * s)
                             : MapPoint(1, real(0.5) - d.z * s, real(0.5) + d.y * s);
    }
    if (ay >= az) {
        real s = real(0.5) / ay;
        return d.y > real(0) ? MapPoint(2, real(0.5) + d.x * s, real(0.5) + d.z * s)
                             : MapPoint(3, real(0.5) + d.x * s, real(0.5) - d.z * s);
    }
    real s = real(0.5) / az;
    return d.z > real(0) ? MapPoint(4, real(0.5) - d.x * s, real(0.5) + d.y * s)
                         : MapPoint(5, real(0.5) + d.x * s, real(0.5) + d.y * s);
}

SHARED_FN MapPoint environmentPoint(int kind, vec3 d) {
    if (kind == ENVIRONMENT_SPHERE) {
        return spherePoint(d);
    }
    if (kind == ENVIRONMENT_BOX) {
        return boxPoint(d);
    }
    return equirectPoint(d);
}

// Texels of level 0 per radian of direction where the map is finest: along
// a meridian of the latitude-longitude image (N over pi), at the mirror
// ball's centre (the reflected angle turns twice as fast as the normal: N/4),
// at a face's centre (N over a quarter turn). The mip level of a ray follows
// from it and the ray's angular footprint (environment_lookup.glsl).
SHARED_FN real environmentTexelsPerRadian(int kind, int side) {
    if (kind == ENVIRONMENT_SPHERE) {
        return real(side) * real(0.25);
    }
    if (kind == ENVIRONMENT_BOX) {
        return real(side) * real(2) / PI;
    }
    return real(side) / PI;
}

// Where level `level` of an image of side N starts, in texels from the
// image's level 0: N^2 + (N/2)^2 + ... over the levels before it, which is
// 4 (N^2 - s^2) / 3 with s = N / 2^level.
SHARED_FN int mipLevelOffset(int side, int level) {
    int s = side >> level;
    return (side * side - s * s) / 3 * 4;
}

// Texels of an image with all its levels down to 1 x 1: (4 N^2 - 1) / 3.
SHARED_FN int mipPyramidTexels(int side) { return (side * side * 4 - 1) / 3; }
