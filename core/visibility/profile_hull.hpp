#pragma once
// The upper convex hull of a terrain profile seen so far along a sweep line, which answers
// "highest elevation angle from the newest point back to any earlier point" in amortised O(1)
// (Timonen and Westerholm, "Scalable Height Field Self-Shadowing", Eurographics 2010).
//
// Earth curvature keeps the hull exact: with s the distance along the line and
// u = z - s^2 / (2 R), the curvature-corrected slope from q back to point i is
// (z_i - z_q)/(s_q - s_i) - (s_q - s_i)/(2 R) = (u_i - u_q)/(s_q - s_i) - s_q / R,
// and the last term is the same for every i, so the maximiser is still a hull vertex of (s, u).
#include <limits>
#include <vector>

namespace ts::visibility {

class ProfileHull {
public:
    void clear() {
        n_ = 0;
        hint_ = 0;
    }
    bool empty() const { return n_ == 0; }

    // Adds point (s, u) (s larger than every earlier point's) and returns the largest slope
    // (u_i - u) / (s - s_i) over the earlier points, or -infinity if there were none: the
    // tangent from the new point is where its hull edge attaches, so the query is free.
    double add(double s, double u) {
        pop_hidden(s, u);
        double slope = kNone;
        if (n_ > 0) slope = (pts_[n_ - 1].u - u) / (s - pts_[n_ - 1].s);
        push(s, u);
        return slope;
    }

    // Adds a point without asking for its tangent.
    void insert(double s, double u) {
        pop_hidden(s, u);
        push(s, u);
    }

    // Largest slope (u_i - u) / (s - s_i) from a point (s, u) beyond every hull point, without
    // adding it: the tangent vertex, where the slopes (unimodal along an upper convex chain) stop
    // rising. Consecutive queries along a sweep line mostly keep their tangent vertex or move it
    // by one or two, so the search walks from the previous answer instead of bisecting: the
    // same vertex, in a step or two of predictable branches instead of ~log2(h) unpredictable
    // ones. -infinity on an empty hull.
    double max_slope_from(double s, double u) {
        if (n_ == 0) return kNone;
        // Whether the slope to vertex k + 1 is at least the slope to vertex k.
        auto rises = [&](std::size_t k) {
            const Point& a = pts_[k];
            const Point& b = pts_[k + 1];
            return (b.u - u) * (s - a.s) >= (a.u - u) * (s - b.s);
        };
        const std::size_t n = n_;
        std::size_t i = std::min(hint_, n - 1);
        while (i + 1 < n && rises(i)) ++i;
        while (i > 0 && !rises(i - 1)) --i;
        hint_ = i;
        return (pts_[i].u - u) / (s - pts_[i].s);
    }

    static constexpr double kNone = -std::numeric_limits<double>::infinity();

private:
    struct Point {
        double s, u;
    };
    // Pop vertices that the new point hides: the last vertex B leaves the upper hull if the
    // one before it, A, is seen at least as high from (s, u).
    void pop_hidden(double s, double u) {
        std::size_t n = n_;  // a local count: the member would be stored back on every pop
        const Point* p = pts_.data();
        while (n >= 2) {
            const Point& a = p[n - 2];
            const Point& b = p[n - 1];
            if ((a.u - u) * (s - b.s) >= (b.u - u) * (s - a.s))
                --n;
            else
                break;
        }
        n_ = n;
    }
    void push(double s, double u) {
        if (n_ == pts_.size()) pts_.resize(2 * n_ + 64);  // grows to the longest line, then never
        pts_[n_++] = {s, u};
    }
    std::vector<Point> pts_;
    std::size_t n_ = 0;
    std::size_t hint_ = 0;  // the last query's tangent vertex
};

// The hull of the points at least `delay` behind the query point: the far field of a line,
// while the receiver's own near field is marched exactly from the texel centre
// (exact_horizons.cpp says why). Points wait in a queue until the sweep is `delay` past them.
class DelayedHull {
public:
    explicit DelayedHull(double delay = 0) : delay_(delay) {}
    void clear() {
        hull_.clear();
        pending_.clear();
        head_ = 0;
    }
    void add(double s, double u) { pending_.push_back({s, u}); }
    // Largest slope from (s, u) to the points at distance >= delay; -infinity if none.
    double query(double s, double u) {
        while (head_ < pending_.size() && pending_[head_].s <= s - delay_) {
            hull_.insert(pending_[head_].s, pending_[head_].u);
            ++head_;
        }
        return hull_.max_slope_from(s, u);
    }

private:
    struct Pending {
        double s, u;
    };
    double delay_;
    ProfileHull hull_;
    std::vector<Pending> pending_;
    std::size_t head_ = 0;
};

}  // namespace ts::visibility
