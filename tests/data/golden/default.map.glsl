Sample map(vec3 p) {
    vec3 p0 = p;
    vec3 p1;
    vec3 p2;
    Sample s0;
    Sample s1;
    p1 = instTranslate(p0, P(52));
    s0 = shapeSample(instSphere(p1, P(53)), M(34));
    p1 = instRotate(p0, P(54), P(55), P(56));
    p2 = instTranslate(p1, P(57));
    s1 = shapeSample(instBox(p2, P(58)), M(40));
    s0 = instUnion(s0, s1);
    s1 = instGround(p0, footprintPoint(p0), P(59), P(60), P(61), M(46));
    s0 = instUnion(s0, s1);
    return s0;
}
