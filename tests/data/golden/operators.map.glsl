Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(46));
    p2 = instTwist(p1, P(47));
    s0 = shapeSample(instBox(p2, P(48)), M(34));
    s0 = instStepScale(s0, p0, P(49));
    p1 = instScale(p0, P(51));
    p2 = instTranslate(p1, P(52));
    p3 = instRepeat(p2, P(53), P(54));
    s1 = shapeSample(instSphere(p3, P(55)), M(40));
    s1 = instRoundDistance(s1, p1, P(56));
    s1 = instScaleDistance(s1, p1, P(57));
    s0 = instSmoothUnion(s0, s1, P(50), 1);
    p1 = instTranslate(p0, P(58));
    s1 = shapeSample(instTorus(p1, P(59)), M(28));
    s1 = instDisplace(s1, p1, P(60));
    p1 = instTranslate(p0, P(62));
    p2 = instMirror(p1, P(63));
    s2 = shapeSample(instCapsule(p2, P(64), P(65)), M(28));
    s1 = instSmoothDifference(s1, s2, P(61), 3);
    s0 = instSmoothUnion(s0, s1, P(50), 1);
    return s0;
}
