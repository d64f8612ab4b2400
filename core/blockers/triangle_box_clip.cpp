#include "core/blockers/triangle_box_clip.hpp"

#include <algorithm>

namespace ts::blockers {

namespace {
// Keeps the side where sign * (p[axis] - bound) <= 0.
void clip_plane(ClippedPolygon& poly, int axis, double bound, double sign) {
    if (poly.size == 0) return;
    ClippedPolygon out;
    for (int i = 0; i < poly.size; ++i) {
        const glm::dvec3& p = poly.corners[std::size_t(i)];
        const glm::dvec3& q = poly.corners[std::size_t((i + 1) % poly.size)];
        const double dp = sign * (p[axis] - bound), dq = sign * (q[axis] - bound);
        if (dp <= 0) out.corners[std::size_t(out.size++)] = p;
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
            glm::dvec3 x = p + (q - p) * (dp / (dp - dq));
            x[axis] = bound;  // exactly on the plane, whatever the rounding
            if (out.size < 9) out.corners[std::size_t(out.size++)] = x;
        }
    }
    poly = out;
}
}  // namespace

ClippedPolygon clip_triangle_to_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                    const glm::dvec3& box_lo, const glm::dvec3& box_hi) {
    ClippedPolygon poly;
    poly.corners[0] = a;
    poly.corners[1] = b;
    poly.corners[2] = c;
    poly.size = 3;
    for (int axis = 0; axis < 3; ++axis) {
        clip_plane(poly, axis, box_hi[axis], 1.0);
        clip_plane(poly, axis, box_lo[axis], -1.0);
    }
    return poly;
}

}  // namespace ts::blockers
