Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    Sample s0;
    Sample s1;
    p1 = instTranslate(p0, P(41));
    s0 = shapeSample(instSphere(p1, P(42)), M(29));
    p1 = instRotate(p0, P(43), P(44), P(45));
    p2 = instTranslate(p1, P(46));
    s1 = shapeSample(instBox(p2, P(47)), M(33));
    s0 = instUnion(s0, s1);
    s1 = instGround(p0, P(48), P(49), P(50), M(37));
    s0 = instUnion(s0, s1);
    return s0;
}
