Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    vec3 p3;
    Sample s0;
    Sample s1;
    Sample s2;
    p1 = instTranslate(p0, P(37));
    p2 = instTwist(p1, P(38));
    s0 = shapeSample(instBox(p2, P(39)), M(29));
    s0 = instStepScale(s0, p0, P(40));
    p1 = instScale(p0, P(42));
    p2 = instTranslate(p1, P(43));
    p3 = instRepeat(p2, P(44), P(45));
    s1 = shapeSample(instSphere(p3, P(46)), M(33));
    s1 = instRoundDistance(s1, p1, P(47));
    s1 = instScaleDistance(s1, p1, P(48));
    s0 = instSmoothUnion(s0, s1, P(41), 1);
    p1 = instTranslate(p0, P(49));
    s1 = shapeSample(instTorus(p1, P(50)), M(25));
    s1 = instDisplace(s1, p1, P(51));
    p1 = instTranslate(p0, P(53));
    p2 = instMirror(p1, P(54));
    s2 = shapeSample(instCapsule(p2, P(55), P(56)), M(25));
    s1 = instSmoothDifference(s1, s2, P(52), 3);
    s0 = instSmoothUnion(s0, s1, P(41), 1);
    return s0;
}
