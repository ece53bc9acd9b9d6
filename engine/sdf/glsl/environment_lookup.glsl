// Sampling the environment map's images with the shared mipmap sampler
// (mipmap_lookup.glsl). Pasted after it in GLSL, included in the driver's
// struct in C++ (cpu/interpreter.inl), like sample_driver.glsl.

SHARED_FN EnvironmentMap sceneEnvironment() { return environmentFromSlots(P(ENVIRONMENT_SLOT)); }

// The radiance the environment sends along -d into a ray travelling along d
// whose cone widens by `angle` radians (a pixel's): the level where a texel
// spans the cone, log2 of the cone's width in level-0 texels.
SHARED_FN vec3 environmentRadiance(vec3 d, real angle) {
    EnvironmentMap e = sceneEnvironment();
    MapPoint m = environmentPoint(e.kind, d);
    real texels = angle * environmentTexelsPerRadian(e.kind, e.side);
    real lod = mipLevelOfFootprint(texels);
    int start = m.face * mipPyramidTexels(e.side);
    // a face's edge may round a hair outside [0, 1]
    real u = mapCoordinate(m.u, false);
    real v = mapCoordinate(m.v, false);
    vec3 c = sampleMipmap(start, e.side, e.levels, u, v, lod, e.kind == ENVIRONMENT_EQUIRECT, false);
    return c * e.intensity;
}
