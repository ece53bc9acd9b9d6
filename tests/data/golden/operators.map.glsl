Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(12));
    p2 = instTwist(p1, P(13));
    s0 = shapeSample(instBox(p2, P(14)), M(4));
    s0 = instStepScale(s0, p0, P(15));
    p1 = instScale(p0, P(17));
    p2 = instTranslate(p1, P(18));
    p3 = instRepeat(p2, P(19), P(20));
    s1 = shapeSample(instSphere(p3, P(21)), M(8));
    s1 = instRoundDistance(s1, p1, P(22));
    s1 = instScaleDistance(s1, p1, P(23));
    s0 = instSmoothUnion(s0, s1, P(16), 1);
    p1 = instTranslate(p0, P(24));
    s1 = shapeSample(instTorus(p1, P(25)), M(0));
    s1 = instDisplace(s1, p1, P(26));
    p1 = instTranslate(p0, P(28));
    p2 = instMirror(p1, P(29));
    s2 = shapeSample(instCapsule(p2, P(30), P(31)), M(0));
    s1 = instSmoothDifference(s1, s2, P(27), 3);
    s0 = instSmoothUnion(s0, s1, P(16), 1);
    return s0;
}
