// Sampling the environment map's images, the same code in both backends: it
// needs T(i), texel i of the backend's texel buffer (GLSL: texelFetch of a
// buffer texture, never the hardware filter, whose bits are not the CPU's;
// C++: the same floats from an array). Pasted after T in GLSL, included in
// the driver's struct in C++ (cpu/interpreter.inl), like sample_driver.glsl.

SHARED_FN EnvironmentMap sceneEnvironment() { return environmentFromSlots(P(ENVIRONMENT_SLOT)); }

// Texel (i, j) of a level `size` texels wide starting at texel `start`:
// columns wrap around when `wrap` (the latitude-longitude map's seam), else
// clamp to the edge like the rows.
SHARED_FN vec3 levelTexel(int start, int size, int i, int j, bool wrap) {
    int column = wrap ? i - size * int(floor(real(i) / real(size))) : clamp(i, 0, size - 1);
    int row = clamp(j, 0, size - 1);
    return xyz(T(start + row * size + column));
}

// Bilinear interpolation between the four texel centres around (u, v).
SHARED_FN vec3 sampleLevel(int start, int size, real u, real v, bool wrap) {
    real x = u * real(size) - real(0.5);
    real y = v * real(size) - real(0.5);
    real x0 = floor(x);
    real y0 = floor(y);
    real fx = x - x0;
    real fy = y - y0;
    int i = int(x0);
    int j = int(y0);
    vec3 bottom = lerp3s(levelTexel(start, size, i, j, wrap), levelTexel(start, size, i + 1, j, wrap), fx);
    vec3 top = lerp3s(levelTexel(start, size, i, j + 1, wrap), levelTexel(start, size, i + 1, j + 1, wrap), fx);
    return lerp3s(bottom, top, fy);
}

// The notes' mipmap access: level lod (0 the full image, fractional between
// two levels), interpolated linearly between the two nearest levels.
SHARED_FN vec3 sampleMipmap(int start, int side, int levels, real u, real v, real lod, bool wrap) {
    real level = clamp(lod, real(0), real(levels - 1));
    int fine = int(floor(level));
    int coarse = min(fine + 1, levels - 1);
    vec3 a = sampleLevel(start + mipLevelOffset(side, fine), side >> fine, u, v, wrap);
    vec3 b = sampleLevel(start + mipLevelOffset(side, coarse), side >> coarse, u, v, wrap);
    return lerp3s(a, b, level - real(fine));
}

// The radiance the environment sends along -d into a ray travelling along d
// whose cone widens by `angle` radians (a pixel's): the level where a texel
// spans the cone, log2 of the cone's width in level-0 texels.
SHARED_FN vec3 environmentRadiance(vec3 d, real angle) {
    EnvironmentMap e = sceneEnvironment();
    MapPoint m = environmentPoint(e.kind, d);
    real texels = angle * environmentTexelsPerRadian(e.kind, e.side);
    real lod = texels > real(1) ? libraryLog2(texels) : real(0);
    int start = m.face * mipPyramidTexels(e.side);
    // clamp: a face's edge may round a hair outside [0, 1], and a NaN (which
    // GLSL's int() leaves undefined) becomes 0 by the library's clamp
    real u = clamp(m.u, real(0), real(1));
    real v = clamp(m.v, real(0), real(1));
    vec3 c = sampleMipmap(start, e.side, e.levels, u, v, lod, e.kind == ENVIRONMENT_EQUIRECT);
    return c * e.intensity;
}
