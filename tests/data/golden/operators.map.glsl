Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(45));
    p2 = instTwist(p1, P(46));
    s0 = shapeSample(instBox(p2, P(47)), M(33));
    s0 = instStepScale(s0, p0, P(48));
    p1 = instScale(p0, P(50));
    p2 = instTranslate(p1, P(51));
    p3 = instRepeat(p2, P(52), P(53));
    s1 = shapeSample(instSphere(p3, P(54)), M(39));
    s1 = instRoundDistance(s1, p1, P(55));
    s1 = instScaleDistance(s1, p1, P(56));
    s0 = instSmoothUnion(s0, s1, P(49), 1);
    p1 = instTranslate(p0, P(57));
    s1 = shapeSample(instTorus(p1, P(58)), M(27));
    s1 = instDisplace(s1, p1, P(59));
    p1 = instTranslate(p0, P(61));
    p2 = instMirror(p1, P(62));
    s2 = shapeSample(instCapsule(p2, P(63), P(64)), M(27));
    s1 = instSmoothDifference(s1, s2, P(60), 3);
    s0 = instSmoothUnion(s0, s1, P(49), 1);
    return s0;
}
