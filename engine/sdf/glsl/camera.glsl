// Primary rays from the orbit camera (thesis, section 2.1; frame built by the host).

struct Camera {
    vec3 origin;      // eye position in march coordinates
    vec3 forward;     // unit
    vec3 right;       // unit
    vec3 up;          // unit
    real tanHalfFov;  // tan(vertical field of view / 2)
};

struct Ray {
    vec3 origin;
    vec3 direction;
};

// (px, py): sample position in pixels from the bottom-left corner of the image,
// pixel centres at half-integers (gl_FragCoord's convention).
SHARED_FN Ray cameraRay(Camera camera, real px, real py, real width, real height) {
    real u = (real(2) * px - width) / height * camera.tanHalfFov;
    real v = (real(2) * py - height) / height * camera.tanHalfFov;
    vec3 direction = normalize3(camera.forward + camera.right * u + camera.up * v);
    return Ray(camera.origin, direction);
}

// Offset of sub-sample `index` (0..aa-1) inside a pixel: (m + 1/2)/AA - 1/2.
SHARED_FN real subsampleOffset(int index, int aa) {
    return (real(index) + real(0.5)) / real(aa) - real(0.5);
}
