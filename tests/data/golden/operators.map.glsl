Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(44));
    p2 = instTwist(p1, P(45));
    s0 = shapeSample(instBox(p2, P(46)), M(32));
    s0 = instStepScale(s0, p0, P(47));
    p1 = instScale(p0, P(49));
    p2 = instTranslate(p1, P(50));
    p3 = instRepeat(p2, P(51), P(52));
    s1 = shapeSample(instSphere(p3, P(53)), M(38));
    s1 = instRoundDistance(s1, p1, P(54));
    s1 = instScaleDistance(s1, p1, P(55));
    s0 = instSmoothUnion(s0, s1, P(48), 1);
    p1 = instTranslate(p0, P(56));
    s1 = shapeSample(instTorus(p1, P(57)), M(26));
    s1 = instDisplace(s1, p1, P(58));
    p1 = instTranslate(p0, P(60));
    p2 = instMirror(p1, P(61));
    s2 = shapeSample(instCapsule(p2, P(62), P(63)), M(26));
    s1 = instSmoothDifference(s1, s2, P(59), 3);
    s0 = instSmoothUnion(s0, s1, P(48), 1);
    return s0;
}
