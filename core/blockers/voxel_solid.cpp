#include "core/blockers/voxel_solid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "core/blockers/triangle_box_clip.hpp"
#include "core/util/parallel_for.hpp"

namespace ts::blockers {

namespace {

constexpr int kBorder = 2;  // free cells around the mesh: the flood fill starts there

struct CellCorner {
    int cell;
    glm::dvec3 p;
};

// 3x3x3 box dilation of a 0/1 grid, as three separable passes.
std::vector<std::uint8_t> dilate(const std::vector<std::uint8_t>& in, const glm::ivec3& d) {
    std::vector<std::uint8_t> a = in, b(in.size());
    const int stride[3] = {1, d.x, d.x * d.y};
    for (int axis = 0; axis < 3; ++axis) {
        for (int k = 0; k < d.z; ++k)
            for (int j = 0; j < d.y; ++j)
                for (int i = 0; i < d.x; ++i) {
                    const int c[3] = {i, j, k};
                    const int idx = (k * d.y + j) * d.x + i;
                    std::uint8_t v = a[std::size_t(idx)];
                    if (c[axis] > 0) v |= a[std::size_t(idx - stride[axis])];
                    if (c[axis] + 1 < d[axis]) v |= a[std::size_t(idx + stride[axis])];
                    b[std::size_t(idx)] = v;
                }
        std::swap(a, b);
    }
    return a;
}

// Cells reachable from the grid's border through cells not blocked (6-connected).
std::vector<std::uint8_t> flood_from_border(const std::vector<std::uint8_t>& blocked, const glm::ivec3& d) {
    std::vector<std::uint8_t> reached(blocked.size(), 0);
    std::vector<int> stack;
    auto push = [&](int idx) {
        if (!blocked[std::size_t(idx)] && !reached[std::size_t(idx)]) {
            reached[std::size_t(idx)] = 1;
            stack.push_back(idx);
        }
    };
    for (int k = 0; k < d.z; ++k)
        for (int j = 0; j < d.y; ++j)
            for (int i = 0; i < d.x; ++i)
                if (i == 0 || j == 0 || k == 0 || i == d.x - 1 || j == d.y - 1 || k == d.z - 1)
                    push((k * d.y + j) * d.x + i);
    while (!stack.empty()) {
        const int idx = stack.back();
        stack.pop_back();
        const int i = idx % d.x, j = (idx / d.x) % d.y, k = idx / (d.x * d.y);
        if (i > 0) push(idx - 1);
        if (i + 1 < d.x) push(idx + 1);
        if (j > 0) push(idx - d.x);
        if (j + 1 < d.y) push(idx + d.x);
        if (k > 0) push(idx - d.x * d.y);
        if (k + 1 < d.z) push(idx + d.x * d.y);
    }
    return reached;
}

bool lex_less(const glm::dvec3& a, const glm::dvec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

}  // namespace

bool VoxelSolid::solid_at(const glm::dvec3& p) const {
    const glm::dvec3 q = (p - origin) / cell;
    const int i = int(std::floor(q.x)), j = int(std::floor(q.y)), k = int(std::floor(q.z));
    if (i < 0 || j < 0 || k < 0 || i >= dims.x || j >= dims.y || k >= dims.z) return false;
    return state[std::size_t(index(i, j, k))] != VoxelState::outside;
}

double VoxelSolid::solid_volume() const {
    const auto n = std::count_if(state.begin(), state.end(), [](VoxelState s) { return s != VoxelState::outside; });
    return double(n) * cell * cell * cell;
}

VoxelSolid voxelize_solid(const mesh::TriangleMesh& mesh, int resolution, int threads) {
    const mesh::Bounds b = mesh::mesh_bounds(mesh);
    const glm::dvec3 size = b.size();
    const double longest = std::max({size.x, size.y, size.z});
    VoxelSolid v;
    v.cell = std::max(longest / std::max(resolution, 1), 1e-6);
    v.origin = b.lo - double(kBorder) * v.cell;
    for (int a = 0; a < 3; ++a) v.dims[a] = int(std::floor(size[a] / v.cell)) + 1 + 2 * kBorder;
    const std::size_t cells = std::size_t(v.dims.x) * std::size_t(v.dims.y) * std::size_t(v.dims.z);

    // 1. Triangle pieces per cell, in parallel over chunks of triangles.
    const int workers = thread_count(threads);
    const int tri_count = int(mesh.triangle_count());
    const int chunks = std::min(tri_count, 64 * workers);
    std::vector<std::vector<CellCorner>> found(static_cast<std::size_t>(workers));
    parallel_for(chunks, workers, [&](int chunk, int worker) {
        auto& out = found[std::size_t(worker)];
        const int t0 = int((long long)tri_count * chunk / chunks), t1 = int((long long)tri_count * (chunk + 1) / chunks);
        for (int t = t0; t < t1; ++t) {
            const glm::dvec3 p0(mesh.positions[std::size_t(3 * t)]), p1(mesh.positions[std::size_t(3 * t + 1)]),
                p2(mesh.positions[std::size_t(3 * t + 2)]);
            const glm::dvec3 lo = (glm::min(p0, glm::min(p1, p2)) - v.origin) / v.cell;
            const glm::dvec3 hi = (glm::max(p0, glm::max(p1, p2)) - v.origin) / v.cell;
            glm::ivec3 c0, c1;
            for (int a = 0; a < 3; ++a) {
                c0[a] = std::clamp(int(std::floor(lo[a])), 0, v.dims[a] - 1);
                c1[a] = std::clamp(int(std::floor(hi[a])), 0, v.dims[a] - 1);
            }
            for (int k = c0.z; k <= c1.z; ++k)
                for (int j = c0.y; j <= c1.y; ++j)
                    for (int i = c0.x; i <= c1.x; ++i) {
                        const int idx = v.index(i, j, k);
                        if (c0 == c1) {  // the whole triangle in one cell: no clipping
                            out.push_back({idx, p0});
                            out.push_back({idx, p1});
                            out.push_back({idx, p2});
                            continue;
                        }
                        const glm::dvec3 box_lo = v.origin + glm::dvec3(i, j, k) * v.cell;
                        const ClippedPolygon poly = clip_triangle_to_box(p0, p1, p2, box_lo, box_lo + v.cell);
                        for (int c = 0; c < poly.size; ++c) out.push_back({idx, poly.corners[std::size_t(c)]});
                    }
        }
    });

    // 2. Counting sort by cell into CSR, duplicates (corners shared by neighbouring triangles) removed.
    std::vector<std::uint32_t> per_cell(cells + 1, 0);
    for (const auto& f : found)
        for (const CellCorner& c : f) ++per_cell[std::size_t(c.cell) + 1];
    for (std::size_t i = 0; i < cells; ++i) per_cell[i + 1] += per_cell[i];
    std::vector<glm::dvec3> sorted(per_cell[cells]);
    {
        std::vector<std::uint32_t> fill(per_cell.begin(), per_cell.end() - 1);
        for (auto& f : found) {
            for (const CellCorner& c : f) sorted[fill[std::size_t(c.cell)]++] = c.p;
            f = {};
        }
    }
    v.state.assign(cells, VoxelState::outside);
    v.corner_begin.push_back(0);
    for (std::size_t cell = 0; cell < cells; ++cell) {
        const std::uint32_t a = per_cell[cell], e = per_cell[cell + 1];
        if (a == e) continue;
        std::sort(sorted.begin() + a, sorted.begin() + e, lex_less);
        const auto last = std::unique(sorted.begin() + a, sorted.begin() + e);
        v.corners.insert(v.corners.end(), sorted.begin() + a, last);
        v.surface_cells.push_back(int(cell));
        v.corner_begin.push_back(std::uint32_t(v.corners.size()));
        v.state[cell] = VoxelState::surface;
    }

    // 3. Inside/outside: close the surface by one cell, flood the outside from the border, and
    // grow the outside back by one cell (a morphological closing), the surface cells kept.
    std::vector<std::uint8_t> surface(cells, 0);
    for (int c : v.surface_cells) surface[std::size_t(c)] = 1;
    const std::vector<std::uint8_t> outside = dilate(flood_from_border(dilate(surface, v.dims), v.dims), v.dims);
    for (std::size_t c = 0; c < cells; ++c)
        if (!surface[c]) v.state[c] = outside[c] ? VoxelState::outside : VoxelState::interior;
    return v;
}

}  // namespace ts::blockers
