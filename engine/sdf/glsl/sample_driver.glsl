// The per-sample driver loop, the same code in both backends, bound included.
// It needs these from its backend: P(slot), a slot of the parameter buffer,
// mapDistance(p), the scene's field for the driver's loop (its distances
// alone where materialSampledApart(), else with materials), mapMaterial(p),
// the field with materials for the material phase taken apart,
// materialSampledApart(), whether it is taken apart (traceSample),
// secondaryRays(), whether the scene has mirrors or glass, environmentMap(),
// whether rays that leave the scene see an image (environment_lookup.glsl,
// which reads T(i)), imageTextures(), whether materials have image textures,
// materialSamplesPerHit(), how many evaluations the material phase takes
// (tracer.glsl's TraceState), setTextureStretch(k), which widens the
// footprint of the next evaluation's image textures (texture_lookup.glsl),
// setFootprintShift(v), which unfolds the next evaluation's footprints
// along the ray's path (footprint_point.glsl),
// and setMaterialReads(bits), which material fields the next evaluation is
// read for (traceMaterialReads). GLSL: the generated functions before it;
// C++: members of the struct this file is included in (cpu/interpreter.inl).
// One call site of each field (compile cost grows with call sites, see
// docs/toolchain-notes.md); the GL backend makes the scene's map() the body
// of only one of them.

SHARED_FN TraceSettings sceneTraceSettings() {
    return traceSettingsFromSlots(P(TRACE_SLOT), P(TRACE_SLOT + 1), P(TRACE_SLOT + 2), P(TRACE_SLOT + 3),
                                  P(TRACE_SLOT + 4), P(TRACE_SLOT + 5), P(TRACE_SLOT + 6));
}

SHARED_FN Camera sceneCamera() {
    return cameraFromSlots(P(CAMERA_SLOT), P(CAMERA_SLOT + 1), P(CAMERA_SLOT + 2), P(CAMERA_SLOT + 3));
}

// Light `index` of the table; an index past the scene's lights reads a zero
// light, which no phase uses (beginLight ends shading at lightCount).
SHARED_FN Light sceneLight(int index) {
    int slot = LIGHT_SLOT + LIGHT_SLOTS * clamp(index, 0, MAX_LIGHTS - 1);
    return lightFromSlots(P(slot), P(slot + 1));
}

// Readies the backend for the evaluation state s asks for next.
SHARED_FN void prepareSample(TraceState s) {
    if (imageTextures()) {
        setTextureStretch(textureFootprintStretch(s));
    }
    if (secondaryRays()) {
        setFootprintShift(footprintShiftOf(s));
    }
    setMaterialReads(traceMaterialReads(s));
}

// The field as the ray sees it: inside a solid it is negated (ray_tree.glsl).
SHARED_FN Sample fieldSeenBy(TraceState s, Sample field) {
    if (secondaryRays() && s.inside) {
        return insideSample(field);
    }
    return field;
}

// One sub-sample at (px, py) pixels from the bottom-left corner of a
// width x height image. The loop ends at PHASE_DONE; traceIterationBound caps
// it for both backends alike (llvmpipe's limiter, docs/toolchain-notes.md).
// A scene with mirrors or glass (secondaryRays(), supplied by the backend
// with P and map: a constant in GLSL, so other scenes compile none of it)
// walks its ray tree in the same loop, under rayTreeIterationBound.
// Where materialSampledApart(), the inner loop evaluates mapDistance() only
// and leaves when the next evaluation is the material phase's; the outer
// loop takes that one with mapMaterial() and the inner loop goes on with it. The
// evaluations and their order are those of a single loop; the point is
// llvmpipe's, which runs every line of a loop's body on every pass for all
// its lanes (docs/toolchain-notes.md): materials in the inner loop would cost
// their work at every step of every phase.
SHARED_FN TraceState traceSample(real px, real py, real width, real height) {
    TraceSettings settings = sceneTraceSettings();
    // a pixel's angular width at the image centre: the footprint of rays
    // that leave the scene (curved mirrors widen it; that is not modelled)
    // and the spacing of image bump maps' samples
    real pixelAngle = real(2) * sceneCamera().tanHalfFov / height;
    TraceState s = traceBegin(cameraRay(sceneCamera(), px, py, width, height));
    s.materialSamples = materialSamplesPerHit();
    s.pixelAngle = pixelAngle;
    Sample field = shapeSample(real(0), s.material);
    RayTree tree = rayTreeBegin();
    int limit = secondaryRays() ? rayTreeIterationBound(settings) : traceIterationBound(settings);
    int i = 0;
    bool sampled = false;  // field is the material sample the inner loop needs next
    bool finished = false;
    while (!finished && i < limit) {
        for (; i < limit; ++i) {
            Light light = sceneLight(lightIndex(s));
            s = skipClearShadowRay(s, light, settings);
            s = skipEmptyMarch(s, settings);
            if (traceNeedsSample(s) && !sampled) {
                if (materialSampledApart() && traceMaterialReads(s) == MATERIAL_READS_SHADING) {
                    break;
                }
                prepareSample(s);
                vec3 p = tracePoint(s, light, settings);
                field = fieldSeenBy(s, withGroundStep(s, p, mapDistance(p), settings));
                s.evaluations = s.evaluations + 1;
            }
            sampled = false;
            s = traceAdvance(s, field, light, settings);
            if (s.phase == PHASE_DONE) {
                if (environmentMap() && !s.hit) {
                    s.color = environmentRadiance(s.rayDirection, pixelAngle);
                }
                if (!secondaryRays()) {
                    finished = true;
                    break;
                }
                tree = rayTreeFinishRay(tree, s, settings);
                if (tree.pending == 0) {
                    finished = true;
                    break;
                }
                s = traceBeginNode(rayTreeTop(tree));
                s.materialSamples = materialSamplesPerHit();
                s.pixelAngle = pixelAngle;
                tree = rayTreePop(tree);
            }
        }
        if (materialSampledApart() && !finished && i < limit) {
            prepareSample(s);
            vec3 p = tracePoint(s, sceneLight(lightIndex(s)), settings);
            field = fieldSeenBy(s, withGroundStep(s, p, mapMaterial(p), settings));
            s.evaluations = s.evaluations + 1;
            sampled = true;
        }
    }
    if (secondaryRays()) {
        s = rayTreeResult(tree, s);
    }
    s.color = s.color * settings.exposure;
    return s;
}
