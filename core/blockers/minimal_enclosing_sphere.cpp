#include "core/blockers/minimal_enclosing_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ts::blockers {

namespace {

constexpr double kPad = 1e-9;

struct Ball {
    glm::dvec3 c{0.0};
    double r2 = -1.0;  // empty
    bool holds(const glm::dvec3& p) const {
        const glm::dvec3 d = p - c;
        return glm::dot(d, d) <= r2 * (1.0 + 1e-12) + 1e-300;
    }
};

Ball ball_of_two(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 c = 0.5 * (a + b);
    return {c, glm::dot(a - c, a - c)};
}

Ball ball_of_three(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, n = glm::cross(ab, ac);
    const double n2 = glm::dot(n, n);
    if (n2 <= 1e-30 * glm::dot(ab, ab) * glm::dot(ac, ac) || n2 == 0.0) {
        // Collinear: the two farthest apart.
        Ball best = ball_of_two(a, b);
        for (const Ball& o : {ball_of_two(a, c), ball_of_two(b, c)})
            if (o.r2 > best.r2) best = o;
        return best;
    }
    const glm::dvec3 off = (glm::dot(ac, ac) * glm::cross(n, ab) + glm::dot(ab, ab) * glm::cross(ac, n)) / (2.0 * n2);
    return {a + off, glm::dot(off, off)};
}

Ball ball_of_four(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a, v = c - a, w = d - a;
    const double det = glm::dot(u, glm::cross(v, w));
    const double scale = glm::length(u) * glm::length(v) * glm::length(w);
    if (!(std::abs(det) > 1e-12 * scale)) {
        // Coplanar support: the largest circumcircle of three, which holds the fourth in exact
        // arithmetic; the radius is fixed up at the end anyway.
        Ball best = ball_of_three(a, b, c);
        for (const Ball& o : {ball_of_three(a, b, d), ball_of_three(a, c, d), ball_of_three(b, c, d)})
            if (o.r2 > best.r2) best = o;
        return best;
    }
    const glm::dvec3 off =
        (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) + glm::dot(w, w) * glm::cross(u, v)) /
        (2.0 * det);
    return {a + off, glm::dot(off, off)};
}

Ball ball_of_support(const glm::dvec3* s, int n) {
    switch (n) {
    case 0: return {};
    case 1: return {s[0], 0.0};
    case 2: return ball_of_two(s[0], s[1]);
    case 3: return ball_of_three(s[0], s[1], s[2]);
    default: return ball_of_four(s[0], s[1], s[2], s[3]);
    }
}

// Welzl, move-to-front: the smallest ball of points[0, end) with support[0, n) on its boundary.
Ball move_to_front(std::vector<glm::dvec3>& points, std::size_t end, glm::dvec3* support, int n) {
    Ball ball = ball_of_support(support, n);
    if (n == 4) return ball;
    for (std::size_t i = 0; i < end; ++i) {
        if (ball.holds(points[i])) continue;
        support[n] = points[i];
        ball = move_to_front(points, i, support, n + 1);
        std::rotate(points.begin(), points.begin() + std::ptrdiff_t(i), points.begin() + std::ptrdiff_t(i) + 1);
    }
    return ball;
}

}  // namespace

double enclosing_radius(std::span<const glm::dvec3> points, const glm::dvec3& center) {
    double r2 = 0.0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 d = p - center;
        r2 = std::max(r2, glm::dot(d, d));
    }
    return std::sqrt(r2) * (1.0 + kPad);
}

Sphere minimal_enclosing_sphere(std::span<const glm::dvec3> points) {
    if (points.empty()) return {glm::dvec3(0.0), 0.0};
    std::vector<glm::dvec3> work(points.begin(), points.end());
    std::mt19937_64 rng(0x5eed);
    std::shuffle(work.begin(), work.end(), rng);
    glm::dvec3 support[4];
    Ball ball = move_to_front(work, work.size(), support, 0);
    glm::dvec3 center = ball.c;
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z)) {
        // Should not happen; the box centre still gives a bounding (if larger) sphere.
        glm::dvec3 lo = points[0], hi = points[0];
        for (const glm::dvec3& p : points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        center = 0.5 * (lo + hi);
    }
    return {center, enclosing_radius(points, center)};
}

}  // namespace ts::blockers
