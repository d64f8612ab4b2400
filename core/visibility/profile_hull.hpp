#pragma once
// The upper convex hull of a terrain profile seen so far along a sweep line, which answers
// "highest elevation angle from the newest point back to any earlier point" in amortised O(1)
// (Timonen and Westerholm, "Scalable Height Field Self-Shadowing", Eurographics 2010).
//
// Earth curvature keeps the hull exact: with s the distance along the line and
// u = z - s^2 / (2 R), the curvature-corrected slope from q back to point i is
// (z_i - z_q)/(s_q - s_i) - (s_q - s_i)/(2 R) = (u_i - u_q)/(s_q - s_i) - s_q / R,
// and the last term is the same for every i, so the maximiser is still a hull vertex of (s, u).
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace ts::visibility {

struct HullPoint {
    double s, u;
};

// The hull as a value: a pointer to storage with room for every point of the line (the owner,
// DelayedHull, provides it) and two counts. Meant to live in a local variable of the sweep's
// inner loop, so the compiler keeps the counts in registers (hence always_inline: a call
// would pass the object through memory).
class ProfileHull {
public:
    ProfileHull() = default;
    explicit ProfileHull(HullPoint* storage) : pts_(storage) {}
    bool empty() const { return n_ == 0; }

    // Adds point q (q.s larger than every earlier point's). Pops the vertices that q hides
    // first: the last vertex B leaves the upper hull if the one before it, A, is seen at
    // least as high from q.
    [[gnu::always_inline]] void insert(HullPoint q) {
        std::size_t n = n_;
        while (n >= 2) {
            const HullPoint& a = pts_[n - 2];
            const HullPoint& b = pts_[n - 1];
            if ((a.u - q.u) * (q.s - b.s) >= (b.u - q.u) * (q.s - a.s))
                --n;
            else
                break;
        }
        pts_[n] = q;
        n_ = n + 1;
    }

    // Largest slope (u_i - u) / (s - s_i) from a point (s, u) beyond every hull point, without
    // adding it: the tangent vertex, where the slopes (unimodal along an upper convex chain) stop
    // rising. Consecutive queries along a sweep line mostly keep their tangent vertex or move it
    // by one or two, so the search walks from the previous answer instead of bisecting: the
    // same vertex, in a step or two of predictable branches instead of ~log2(h) unpredictable
    // ones. -infinity on an empty hull.
    [[gnu::always_inline]] double max_slope_from(double s, double u) {
        const std::size_t n = n_;
        if (n == 0) return kNone;
        // Whether the slope to vertex k + 1 is at least the slope to vertex k.
        auto rises = [&](std::size_t k) {
            const HullPoint& a = pts_[k];
            const HullPoint& b = pts_[k + 1];
            return (b.u - u) * (s - a.s) >= (a.u - u) * (s - b.s);
        };
        std::size_t i = std::min(hint_, n - 1);
        if (i + 1 < n && rises(i)) {
            do ++i;
            while (i + 1 < n && rises(i));
        } else {
            // Only when it did not move forward: after a step forward rises(i - 1) is known to
            // hold, and the backward walk would stop at once.
            while (i > 0 && !rises(i - 1)) --i;
        }
        hint_ = i;
        return (pts_[i].u - u) / (s - pts_[i].s);
    }

    static constexpr double kNone = -std::numeric_limits<double>::infinity();

private:
    HullPoint* pts_ = nullptr;
    std::size_t n_ = 0;
    std::size_t hint_ = 0;  // the last query's tangent vertex
};

// The hull of the points at least `delay` behind the query point: the far field of a line,
// while the receiver's own near field is marched exactly from the texel centre
// (exact_horizons.cpp says why). The line's points are kept in order and the hull takes them
// in from an index that trails the query by `delay` (no queue to push and pop).
class DelayedHull {
public:
    // One line's state: pointers into the DelayedHull's storage and counts, for a local
    // variable of the sweep's inner loop (the counts stay in registers).
    class Line {
    public:
        // Adds a blocker (s larger than every earlier point's); at most `capacity` of
        // begin_line per line.
        [[gnu::always_inline]] void add(double s, double u) { line_[n_line_++] = {s, u}; }
        // Largest slope (u_i - u) / (s - s_i) to the points at distance >= delay; -infinity
        // if none.
        [[gnu::always_inline]] double query(double s, double u) {
            const double reach = s - delay_;
            while (head_ < n_line_ && line_[head_].s <= reach) hull_.insert(line_[head_++]);
            return hull_.max_slope_from(s, u);
        }

    private:
        friend class DelayedHull;
        HullPoint* line_ = nullptr;          // every point added, in order
        std::size_t n_line_ = 0, head_ = 0;  // line_[0, head_) are in the hull
        ProfileHull hull_;
        double delay_ = 0;
    };

    explicit DelayedHull(double delay = 0) : delay_(delay) {}

    // An empty line with room for `capacity` points; it points into this object's storage, so
    // use it before the next begin_line.
    Line begin_line(std::size_t capacity) {
        if (line_.size() < capacity) line_.resize(capacity), hull_.resize(capacity);
        Line l;
        l.line_ = line_.data();
        l.hull_ = ProfileHull(hull_.data());
        l.delay_ = delay_;
        return l;
    }

private:
    double delay_;
    std::vector<HullPoint> line_, hull_;  // scratch reused by every line
};

}  // namespace ts::visibility
