#include "core/blockers/receiver_blockers.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::blockers {

namespace {

// Whether sphere s subtends more than the threshold from the origin (the receiver), or holds it.
bool significant(const Sphere& s, double min_sine) {
    const double d2 = glm::dot(s.center, s.center);
    return d2 <= s.radius * s.radius || s.radius / std::sqrt(d2) > min_sine;
}

// The walk of collect_sky_blockers into either kind of output (both have push_back(Sphere)).
template <class Out>
void collect_into(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal, double min_sine,
                  const RatioAttenuation& options, Out& out) {
    const std::vector<SphereNode>& nodes = mesh.hierarchy.nodes;
    if (nodes.empty()) return;
    auto rel = [&](const Sphere& s) { return Sphere{s.center - receiver, s.radius}; };
    auto above_plane = [&](const Sphere& s) {  // s relative to the receiver
        if (!options.cull_lower_hemisphere) return true;
        const double d2 = glm::dot(s.center, s.center);
        if (d2 <= s.radius * s.radius) return true;  // inside: the whole sphere of directions
        const double d = std::sqrt(d2);
        // Cap wholly below the tangent plane: the angle to the normal exceeds 90 deg + theta_b.
        return !(glm::dot(s.center, normal) / d < -s.radius / d);
    };
    // Every leaf below node i that reaches above the plane: the node is significant while its
    // spheres alone are not, so they count together (their union matters).
    auto emit_all = [&](int i) {
        int stack[64];
        int top = 0;
        stack[top++] = i;
        while (top > 0) {
            const SphereNode& n = nodes[std::size_t(stack[--top])];
            if (!above_plane(rel(n.bound))) continue;
            if (n.is_leaf()) {
                out.push_back(rel(mesh.spheres[std::size_t(n.sphere)]));
                continue;
            }
            stack[top++] = n.right;
            stack[top++] = n.left;
        }
    };
    // Level of detail: walk down through significant nodes. A child below the threshold whose
    // sibling is above it is a small part beside a large one: dropped (its whole subtree
    // subtends less than the threshold). A node whose two children are both below it is the
    // finest piece that still matters: all its spheres count, however small each is. So a
    // sphere above the threshold always counts, and a finer decomposition keeps the shadow of
    // the pieces a coarser one keeps: the dropped parts are set by the mesh's shape at the
    // threshold's scale, not by the sphere count.
    if (!significant(rel(nodes[0].bound), min_sine)) return;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const int i = stack[--top];
        const SphereNode& n = nodes[std::size_t(i)];
        if (!above_plane(rel(n.bound))) continue;
        if (n.is_leaf()) {
            out.push_back(rel(mesh.spheres[std::size_t(n.sphere)]));
            continue;
        }
        const bool left = significant(rel(nodes[std::size_t(n.left)].bound), min_sine);
        const bool right = significant(rel(nodes[std::size_t(n.right)].bound), min_sine);
        if (!left && !right) {
            emit_all(i);
            continue;
        }
        if (right) stack[top++] = n.right;
        if (left) stack[top++] = n.left;
    }
}

}  // namespace

void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, std::vector<Sphere>& out) {
    collect_into(mesh, receiver, normal, min_sine, options, out);
}

void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, SphereLanes& out) {
    collect_into(mesh, receiver, normal, min_sine, options, out);
}

double sun_visible_past(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius) {
    // A sphere whose cap stays sun_radius clear of the sun's centre hides none of the disc.
    auto keep = [&](const Sphere& s) {
        const glm::dvec3 v = s.center - receiver;
        const double d = glm::length(v);
        if (d <= s.radius) return true;
        const double cap = std::asin(s.radius / d);
        const double along = glm::dot(v, sun) / d;
        const double limit = cap + sun_radius;
        return limit >= kPi || along > std::cos(limit);
    };
    double visible = 1.0;
    visit_leaves(mesh.hierarchy, keep, [&](int i) {
        if (visible > 0.0) visible *= 1.0 - sphere_sun_cover(mesh.spheres[std::size_t(i)], receiver, sun, sun_radius);
    });
    return visible;
}

double sun_visible_past_triangles(const PlacedSpheres& mesh, const glm::dvec3& receiver,
                                  std::span<const glm::dvec3> disc) {
    if (disc.empty()) return 1.0;
    // The rays in the model frame, where the triangles' BVH was built once for every placement.
    const glm::dvec3 origin = mesh.frame_to_model * (receiver - mesh.model_origin);
    int seen = 0;
    for (const glm::dvec3& d : disc) seen += !mesh.model_triangles->occluded(origin, mesh.frame_to_model * d);
    return double(seen) / double(disc.size());
}

}  // namespace ts::blockers
