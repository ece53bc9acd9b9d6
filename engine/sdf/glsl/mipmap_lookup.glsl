// Sampling a mipmapped image (environment maps and image textures alike), the
// same code in both backends: it needs T(i), texel i of the backend's texel
// buffer (GLSL: texelFetch of a buffer texture, never the hardware filter,
// whose bits are not the CPU's; C++: the same floats from an array). Pasted
// after T in GLSL, included in the CPU kernel's texel reader (cpu/interpreter.inl).
// An image of side N starts at texel `start`, level after level
// (environment.glsl's mipLevelOffset), rows from the bottom.

// Texel (i, j) of a level `size` texels wide starting at texel `start`: a
// coordinate that wraps goes round (a seam, a tiled texture), the others
// clamp to the edge.
SHARED_FN vec3 levelTexel(int start, int size, int i, int j, bool wrapU, bool wrapV) {
    int column = wrapU ? i - size * int(floor(real(i) / real(size))) : clamp(i, 0, size - 1);
    int row = wrapV ? j - size * int(floor(real(j) / real(size))) : clamp(j, 0, size - 1);
    return xyz(T(start + row * size + column));
}

// Bilinear interpolation between the four texel centres around (u, v).
SHARED_FN vec3 sampleLevel(int start, int size, real u, real v, bool wrapU, bool wrapV) {
    real x = u * real(size) - real(0.5);
    real y = v * real(size) - real(0.5);
    real x0 = floor(x);
    real y0 = floor(y);
    real fx = x - x0;
    real fy = y - y0;
    int i = int(x0);
    int j = int(y0);
    vec3 bottom = lerp3s(levelTexel(start, size, i, j, wrapU, wrapV), levelTexel(start, size, i + 1, j, wrapU, wrapV),
                         fx);
    vec3 top = lerp3s(levelTexel(start, size, i, j + 1, wrapU, wrapV),
                      levelTexel(start, size, i + 1, j + 1, wrapU, wrapV), fx);
    return lerp3s(bottom, top, fy);
}

// The notes' mipmap access: level lod (0 the full image, fractional between
// two levels), interpolated linearly between the two nearest levels. An image
// that was not read (no levels: picking and point queries read no texels) is
// white, which leaves what it multiplies as it is (and keeps the level shifts
// below from going negative, undefined in GLSL and C++).
SHARED_FN vec3 sampleMipmap(int start, int side, int levels, real u, real v, real lod, bool wrapU, bool wrapV) {
    if (levels < 1) {
        return vec3(real(1));
    }
    real level = clamp(lod, real(0), real(levels - 1));
    int fine = int(floor(level));
    int coarse = min(fine + 1, levels - 1);
    vec3 a = sampleLevel(start + mipLevelOffset(side, fine), side >> fine, u, v, wrapU, wrapV);
    vec3 b = sampleLevel(start + mipLevelOffset(side, coarse), side >> coarse, u, v, wrapU, wrapV);
    return lerp3s(a, b, level - real(fine));
}

// The level whose texels span a footprint `texels` level-0 texels wide.
SHARED_FN real mipLevelOfFootprint(real texels) { return texels > real(1) ? libraryLog2(texels) : real(0); }
