Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    Sample s0;
    Sample s1;
    p1 = instTranslate(p0, P(16));
    s0 = shapeSample(instSphere(p1, P(17)), M(4));
    p1 = instRotate(p0, P(18), P(19), P(20));
    p2 = instTranslate(p1, P(21));
    s1 = shapeSample(instBox(p2, P(22)), M(8));
    s0 = instUnion(s0, s1);
    s1 = instGround(p0, P(23), P(24), P(25), M(12));
    s0 = instUnion(s0, s1);
    return s0;
}
