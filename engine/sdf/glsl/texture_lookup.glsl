// Image textures (lecture notes on realism, 1.1): a primitive's sample with
// its ambient and diffuse colour (and its specular colour when the material
// asks, texture_specular) multiplied by its image at the point's
// (u, v) (texture_mapping.glsl), filtered by the notes' mipmaps over the
// sample's footprint, widened by textureStretch (the backend's: the tracer
// sets it for the evaluation whose material it shades, tracer.glsl's
// textureFootprintStretch). Needs the shared mipmap sampler
// (mipmap_lookup.glsl), so it follows T(i) like it; the generated map()
// calls it as the ImageTexture opcode.
//
// q0 = (mapping, (u, v) units per scene unit of footprint at distance 1,
// role, bump depth): the role IMAGE_AS_* (texture.glsl),
// q1, q2 = the primitive's slots as its mapping reads them,
// q3 = (first texel, side, levels, 0) of the image: filled in where the
// images are read (program/scene_images.cpp), so another file is a parameter edit.
SHARED_FN vec3 imageTextureColor(vec3 p, real distance, vec4 q0, vec4 q1, vec4 q2, vec4 q3) {
    int start = int(q3.x);
    int side = int(q3.y);
    int levels = int(q3.z);
    TexturePoint t = texturePoint(int(q0.x), p, q1, q2);
    real u = mapCoordinate(t.u, t.wrapU);
    real v = mapCoordinate(t.v, t.wrapV);
    real lod = mipLevelOfFootprint(q0.y * distance * textureStretch * real(side));
    return sampleMipmap(start, side, levels, u, v, lod, t.wrapU, t.wrapV);
}

// The sample with the image's colour c in the role q0.z gives it: its
// colours multiplied by c, or, for a bump map (lecture notes 1.2), its bump
// height the grey value of c (the mean of its channels) times the depth q0.w,
// which the tracer differentiates over the material phase's samples around
// the hit (tracer.glsl).
SHARED_FN Sample imageTexturedSample(Sample s, vec3 c, vec4 q0) {
    int role = int(q0.z);
    Material m = s.material;
    if (role == IMAGE_AS_BUMP) {
        m.bump = q0.w * ((c.x + c.y + c.z) / real(3));
        return Sample(s.d, s.step, m);
    }
    m.ambient = m.ambient * c;
    m.diffuse = m.diffuse * c;
    if (role == IMAGE_AS_COLOR_AND_SPECULAR) {
        m.specular = m.specular * c;
    }
    return Sample(s.d, s.step, m);
}

// ---- ImageTexture: S[dst] = f(S[a], P[b], F, slots) ----
// A textureStretch of 0: the evaluation's colour is not shaded, nothing to look up.
SHARED_FN Sample instImageTexture(Sample s, vec3 p, vec3 f, vec4 q0, vec4 q1, vec4 q2, vec4 q3) {
    if (!(textureStretch > real(0))) {
        return s;
    }
    return imageTexturedSample(s, imageTextureColor(p, length3(f), q0, q1, q2, q3), q0);
}

// Triplanar mapping, for primitives without a parametrization (formulas):
// the image projected along each object axis, in tiles of the texture's
// scale, the three blended by the fourth powers of the object-space normal's
// components, so each projection shows where it is least stretched. The
// normal is the formula's gradient at the point, which the instruction reads
// with the formula (value, gradient) like an implicit surface.
SHARED_FN vec3 triplanarColor(vec3 p, vec3 gradient, real distance, vec4 q0, vec4 q1) {
    int start = int(q1.x);
    int side = int(q1.y);
    int levels = int(q1.z);
    vec3 a = abs(normalize3(gradient));
    vec3 w = a * a * a * a;
    real total = w.x + w.y + w.z;
    w = total > real(0) ? w / total : vec3(real(1) / real(3));
    vec3 t = p * q0.x;
    real lod = mipLevelOfFootprint(q0.y * distance * textureStretch * real(side));
    real x = mapCoordinate(t.x, true);
    real y = mapCoordinate(t.y, true);
    real z = mapCoordinate(t.z, true);
    vec3 alongX = sampleMipmap(start, side, levels, z, y, lod, true, true);
    vec3 alongY = sampleMipmap(start, side, levels, x, z, lod, true, true);
    vec3 alongZ = sampleMipmap(start, side, levels, x, y, lod, true, true);
    return alongX * w.x + alongY * w.y + alongZ * w.z;
}

// ---- TriplanarTexture: S[dst] = f(S[a], P[b], F, formula value and gradient at P[b], slots) ----
// q0 = (tiles per object unit, tiles per scene unit of footprint at distance 1,
// role, bump depth) as ImageTexture's,
// q1 = (first texel, side, levels, 0) of the image, filled in like ImageTexture's q3.
SHARED_FN Sample instTriplanarTexture(Sample s, vec3 p, vec3 f, vec4 v, vec4 q0, vec4 q1) {
    if (!(textureStretch > real(0))) {
        return s;
    }
    return imageTexturedSample(s, triplanarColor(p, vec3(v.y, v.z, v.w), length3(f), q0, q1), q0);
}
