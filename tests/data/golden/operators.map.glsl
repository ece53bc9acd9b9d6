Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(43));
    p2 = instTwist(p1, P(44));
    s0 = shapeSample(instBox(p2, P(45)), M(31));
    s0 = instStepScale(s0, p0, P(46));
    p1 = instScale(p0, P(48));
    p2 = instTranslate(p1, P(49));
    p3 = instRepeat(p2, P(50), P(51));
    s1 = shapeSample(instSphere(p3, P(52)), M(37));
    s1 = instRoundDistance(s1, p1, P(53));
    s1 = instScaleDistance(s1, p1, P(54));
    s0 = instSmoothUnion(s0, s1, P(47), 1);
    p1 = instTranslate(p0, P(55));
    s1 = shapeSample(instTorus(p1, P(56)), M(25));
    s1 = instDisplace(s1, p1, P(57));
    p1 = instTranslate(p0, P(59));
    p2 = instMirror(p1, P(60));
    s2 = shapeSample(instCapsule(p2, P(61), P(62)), M(25));
    s1 = instSmoothDifference(s1, s2, P(58), 3);
    s0 = instSmoothUnion(s0, s1, P(47), 1);
    return s0;
}
