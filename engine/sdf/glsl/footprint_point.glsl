// The point a sample's footprint is measured from. Filtered patterns (the
// ground's checker and grid lines, material textures and bump maps, image
// textures) take their width from its distance to the eye, and the floor
// the stretch of its ellipse from its direction. March coordinates put the
// eye at 0, so for a primary ray it is the march point itself. A ray of the
// tree (ray_tree.glsl) has come pathLength from the eye to its origin: its
// points are measured where they would lie if that path were unfolded into
// one straight line from the eye along the ray's direction (what a flat
// mirror shows is its virtual image), the march point plus footprintShift.
// footprintShift is the backend's, set by the driver before each evaluation
// (sample_driver.glsl, ray_tree.glsl's footprintShiftOf); w = 0: no shift.
// Exact for flat mirrors. Curved mirrors and refracting faces (even flat
// ones) widen or narrow a footprint further; that is not modelled.
SHARED_FN vec3 footprintPoint(vec3 p) {
    if (footprintShift.w > real(0)) {
        return p + xyz(footprintShift);
    }
    return p;
}
