// Procedural colour textures (lecture notes on realism, 1.1), solid: a
// pattern of the primitive's object-space point, so it moves with its node
// and needs no (u, v) parametrization (booleans, formulas and deformed
// shapes included). Like the ground's patterns (material.glsl) each is
// filtered over the sample's footprint: an isotropic width w across the ray,
// in texture units. The pattern's coverage mixes the material's ambient and
// diffuse colour towards the texture colour, and its specular colour too
// when the material asks (texture_specular).
const int TEXTURE_NONE = 0;
const int TEXTURE_CHECKER = 1;  // cubes of side `scale`, alternating
const int TEXTURE_STRIPES = 2;  // slabs of thickness `scale` stacked along object y
const int TEXTURE_NOISE = 3;    // value noise of feature size `scale`, two octaves
const int TEXTURE_IMAGE = 4;    // an image at the primitive's (u, v): texture_lookup.glsl, not a pattern

// What an image does to the sample it is looked up for (texture_lookup.glsl's
// imageTexturedSample; the ImageTexture and TriplanarTexture instructions' q0.z).
const int IMAGE_AS_COLOR = 0;               // multiplies the ambient and diffuse colours
const int IMAGE_AS_COLOR_AND_SPECULAR = 1;  // and the specular colour (texture_specular)
const int IMAGE_AS_BUMP = 2;                // its grey value times q0.w is the bump height

SHARED_FN real fractr(real x) { return x - floor(x); }

// A hash of a lattice point into [0, 1) from + and * only (Hoskins's "hash
// without sine"), so float GLSL and float C++ give the same bits; sin-based
// hashes depend on the built-in's accuracy far from 0.
SHARED_FN real latticeHash(vec3 c) {
    vec3 q = vec3(fractr(c.x * real(0.1031)), fractr(c.y * real(0.1030)), fractr(c.z * real(0.0973)));
    real k = dot3(q, vec3(q.y + real(33.33), q.z + real(33.33), q.x + real(33.33)));
    q = q + vec3(k);
    return fractr((q.x + q.y) * q.z);
}

// Trilinear interpolation of the lattice's hashes with the smoothstep fade; mean 1/2.
SHARED_FN real valueNoise(vec3 x) {
    vec3 i = vec3(floor(x.x), floor(x.y), floor(x.z));
    vec3 f = x - i;
    vec3 u = f * f * (vec3(real(3)) - real(2) * f);
    real h000 = latticeHash(i);
    real h100 = latticeHash(i + vec3(real(1), real(0), real(0)));
    real h010 = latticeHash(i + vec3(real(0), real(1), real(0)));
    real h110 = latticeHash(i + vec3(real(1), real(1), real(0)));
    real h001 = latticeHash(i + vec3(real(0), real(0), real(1)));
    real h101 = latticeHash(i + vec3(real(1), real(0), real(1)));
    real h011 = latticeHash(i + vec3(real(0), real(1), real(1)));
    real h111 = latticeHash(i + vec3(real(1), real(1), real(1)));
    real a = lerpr(lerpr(h000, h100, u.x), lerpr(h010, h110, u.x), u.y);
    real b = lerpr(lerpr(h001, h101, u.x), lerpr(h011, h111, u.x), u.y);
    return lerpr(a, b, u.z);
}

// Noise has no closed-form box filter: an octave of feature size 1 keeps its
// detail while the footprint is under a quarter of a feature and fades to
// its mean (1/2) by a whole feature (a documented approximation).
SHARED_FN real noiseOctave(vec3 x, real w) {
    return lerpr(valueNoise(x), real(0.5), smoothstepr(real(0.25), real(1), w));
}

// The share of texture colour at texture-space point x with footprint w.
SHARED_FN real textureCoverage(int pattern, vec3 x, real w) {
    if (pattern == TEXTURE_CHECKER) {
        // the product first: Mesa regroups a chain of products with a constant factor
        real xy = filteredCheckerWave(x.x, w) * filteredCheckerWave(x.y, w);
        real xyz = xy * filteredCheckerWave(x.z, w);
        return real(0.5) - real(0.5) * xyz;
    }
    if (pattern == TEXTURE_STRIPES) {
        return real(0.5) - real(0.5) * filteredCheckerWave(x.y, w);
    }
    if (pattern == TEXTURE_NOISE) {
        real fine = noiseOctave(x * real(2) + vec3(real(17.5)), real(2) * w);
        return saturate((real(2) * noiseOctave(x, w) + fine) / real(3));
    }
    return real(0);
}

SHARED_FN Material texturedMaterial(Material base, int pattern, vec3 x, real w, vec3 textureColor, bool specular) {
    real coverage = textureCoverage(pattern, x, w);
    Material m = base;
    m.ambient = lerp3s(base.ambient, textureColor, coverage);
    m.diffuse = lerp3s(base.diffuse, textureColor, coverage);
    if (specular) {
        m.specular = lerp3s(base.specular, textureColor, coverage);
    }
    return m;
}

// Bump maps (lecture notes on realism, 1.2): a height field f_h of the
// primitive's object-space point, in [0, 1], times the material's depth (in
// scene units) in Material.bump. The tracer perturbs the shading normal by
// its gradient, estimated from the four samples it takes for the normal
// (tracer.glsl), so a bump map needs no (u, v) parametrization and works on
// booleans, formulas and deformed shapes alike; the surface and its shadows
// do not change. Filtered like the textures: detail finer than the footprint
// fades to the mean height, whose gradient is zero, instead of sparkling.
const int BUMP_NONE = 0;
const int BUMP_NOISE = 1;  // value noise of feature size `scale`, two octaves
const int BUMP_WAVES = 2;  // parallel waves of wavelength `scale` along object x
const int BUMP_IMAGE = 3;  // a grey image at the primitive's (u, v): texture_lookup.glsl, not a pattern

SHARED_FN real bumpHeight(int pattern, vec3 x, real w) {
    if (pattern == BUMP_NOISE) {
        return textureCoverage(TEXTURE_NOISE, x, w);
    }
    if (pattern == BUMP_WAVES) {
        real wave = real(0.5) + real(0.5) * librarySin(real(6.28318531) * x.x);
        return lerpr(wave, real(0.5), smoothstepr(real(0.25), real(1), w));
    }
    return real(0);
}
