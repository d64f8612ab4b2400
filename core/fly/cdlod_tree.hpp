#pragma once
// Continuous level of detail for the flythrough's terrain: a CDLOD quadtree (Strugar 2010)
// over the DEM grid. Level k draws a patch of N x N quads with a vertex every 2^k level-0
// texels; every level has one distance range r_k (metres from the eye), chosen so that the
// projected geometric error stays under a pixel budget:
//
//   screen error (px) = delta * K / d,   K = viewport height / (2 tan(vertical fov / 2))
//
// with delta_k a high quantile (error_quantile, 0.99 by default; 1 = the largest) of the vertical
// distance, over every texel of the DEM, between the level-0 heights and the level-k mesh (the
// same triangles the GPU draws), made non-decreasing in k. The largest one is kept beside it and
// reported: on a coarse DEM of mountains a few peaks and cliff texels stand hundreds of metres
// off their neighbours' mesh, and the strict maximum would keep the whole DEM at full resolution. Level k is
// used out to r_k and morphs into level k+1 over its last (1 - morph_start_ratio) of it
// (cdlod_shared.h), so within its band it shows at worst delta_{k+1} from distance
// morph_start_ratio * r_k on:  r_k >= delta_{k+1} K / (morph_start_ratio * tau).
// Crack-free needs neighbours at most one level apart and a finer patch fully morphed where
// it meets a coarser one: r_k >= 2 r_{k-1} and morph_start_ratio * r_{k+1} >= r_k + the
// largest node diagonal of level k (3D), both enforced. The top level reaches to infinity.
//
// Selection (each frame, on the CPU): from the root, a node outside its frustum is dropped; a
// node the next finer range does not reach is drawn whole; else each child is selected at the
// finer level, or, if that range does not reach it, drawn as that quadrant of this node's patch.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/fly/grid_frame.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::fly {

struct CdlodOptions {
    // Quads per patch side (a power of two >= 2). Smaller patches follow the ranges more
    // closely (fewer triangles) at more draws per frame.
    int patch_quads = 16;
    // The screen-space geometric error goal tau in pixels (Cesium's default is 2).
    double pixel_error = 2.0;
    // Where in its range a level starts morphing into the next (0..1).
    double morph_start_ratio = 0.7;
    // Which quantile of the per-texel mesh errors delta_k is (0.5..1; 1 = the maximum, a strict
    // bound everywhere).
    double error_quantile = 0.99;
};

// One draw: a patch (or one quadrant of it) of a level.
struct CdlodPatch {
    float col0 = 0, row0 = 0;   // level-0 texel-centre coordinates of the patch's first vertex
    float spacing = 1;          // level-0 texels between vertices (2^level)
    int level = 0;
    int quadrant = -1;          // -1: the whole patch; 0..3: NW, NE, SW, SE quarter
    float morph_start_m = 0, morph_end_m = 0;
    // Where its heights and radiance are read: a streamed DEM's detail tile (its atlas slot and
    // its first sample's level-0 texel), or -1: the overview (every level of a DEM in memory).
    int slot = -1;
    float tile_col0 = 0, tile_row0 = 0;
};

// What the selection sees: the eye in the GridFrame's metres (x east, y north, z height above
// the datum) and the view-projection matrix taking eye-relative metres (the same frame minus
// the eye) to clip space (Vulkan depth 0..1).
struct CdlodView {
    glm::dvec3 eye{0.0};
    glm::dmat4 eye_relative_view_projection{1.0};
    double viewport_height_px = 540;
    double vertical_fov_rad = 0.6;
};

struct CdlodSelection {
    std::vector<CdlodPatch> patches;
    std::size_t triangles = 0;
    // Nodes drawn coarser than their range asks because the finer level's tile was not resident
    // (a streamed DEM while it loads; CdlodDetail). 0 once every tile the view needs is in.
    std::size_t coarse_fallbacks = 0;
    // The bound on the screen-space geometric error of what was selected (px): the largest
    // delta_{k+1} K / d over patches, d the nearest distance of the patch's box beyond its
    // morph start (delta_k K / d for an unmorphed part nearer than it).
    double screen_error_px = 0;
    // The same bound with the largest per-texel error of each level instead of the quantile.
    double screen_error_max_px = 0;
};

// What the tree keeps of a terrain: the per-level mesh errors, and the height range of every node
// of the levels from `stored_level` up. A DEM in memory stores every level (stored_level 0); a
// streamed one (core/fly/terrain_overview.hpp) only the coarse ones, the finer nodes' ranges
// coming from the tiles resident at the time (CdlodDetail).
struct CdlodSummary {
    int width = 0, height = 0;        // level-0 texels of the grid
    int stored_level = 0;
    std::vector<double> error_m;      // delta_k at the options' quantile, k = 0..levels (0 at 0)
    std::vector<double> max_error_m;  // the largest per-texel error
    // Per level below stored_level: the largest 3D diagonal of one of its nodes' boxes (m), for
    // the crack-free range condition (cdlod_node_box).
    std::vector<double> detail_diag_m;
    // Per level from stored_level up (index level - stored_level): each node's lowest and highest
    // height, row-major over the level's nodes.
    std::vector<std::vector<glm::vec2>> node_z;
};

// The number of levels and of nodes per level of a width x height grid with patches of
// `patch_quads` quads (a node of level k covers patch_quads 2^k texels a side).
int cdlod_level_count(int width, int height, int patch_quads);
glm::ivec2 cdlod_node_count(int width, int height, int patch_quads, int level);

// The metric box of node (level, ix, iy) with heights in [z.x, z.y]: its four corner texels in
// the frame, clamped onto the grid. lo and hi.
void cdlod_node_box(const GridFrame& frame, int patch_quads, int level, int ix, int iy, glm::vec2 z, glm::dvec3& lo,
                    glm::dvec3& hi);

// The mesh errors and node ranges of a grid in memory (every level stored).
CdlodSummary summarize_cdlod(const terrain::HeightGrid& grid, const CdlodOptions& options);

// The levels below CdlodSummary::stored_level of a streamed DEM: answered from its resident tiles.
class CdlodDetail {
public:
    virtual ~CdlodDetail() = default;
    // The height range of node (level, ix, iy); false when its tile is not resident (its parent
    // is then drawn whole, coarser than the range asks).
    virtual bool node_z_range(int level, int ix, int iy, glm::vec2& z) = 0;
    // The selection wanted node (level, ix, iy) and found its tile missing; `distance_m` from the
    // eye orders the loads.
    virtual void request(int level, int ix, int iy, double distance_m) = 0;
};

class CdlodTree {
public:
    CdlodTree(const terrain::HeightGrid& grid, const GridFrame& frame, const CdlodOptions& options = {});
    // From a summary; levels below its stored_level come from `detail` (which must outlive the
    // tree; may be null when every level is stored).
    CdlodTree(CdlodSummary summary, const GridFrame& frame, const CdlodOptions& options, CdlodDetail* detail = nullptr);
    int stored_level() const { return stored_level_; }

    int levels() const { return levels_; }
    int patch_quads() const { return options_.patch_quads; }
    const CdlodOptions& options() const { return options_; }
    // delta_k (metres, the quantile the ranges use), level 0 = 0; and the largest per-texel error.
    double level_error_m(int level) const { return error_m_[std::size_t(level)]; }
    double level_max_error_m(int level) const { return max_error_m_[std::size_t(level)]; }
    // r_k for a view (metres); the top level's is infinite.
    double range_m(int level, double k_px) const;
    std::size_t triangles_per_patch() const { return std::size_t(2) * std::size_t(options_.patch_quads * options_.patch_quads); }

    void select(const CdlodView& view, CdlodSelection& out) const;

private:
    struct Box {
        glm::dvec3 lo{0.0}, hi{0.0};
    };
    struct Node {
        Box box;
    };
    // Ranges for this K, cached by select().
    void compute_ranges(double k_px, std::vector<double>& ranges) const;
    bool select_node(int level, int ix, int iy, const Box& b, const CdlodView& view, const std::vector<double>& ranges,
                     double k_px, CdlodSelection& out) const;
    // The box of a node: stored, or from the detail (false when its tile is not resident).
    bool node_box(int level, int ix, int iy, Box& out) const;
    Box node_box_of(int level, int ix, int iy, glm::vec2 z) const;
    int nodes_x(int level) const { return nodes_x_[std::size_t(level)]; }
    int nodes_y(int level) const { return nodes_y_[std::size_t(level)]; }
    double node_texels(int level) const { return double(options_.patch_quads) * double(1 << level); }

    void init(CdlodSummary summary);

    const GridFrame& frame_;
    CdlodOptions options_;
    CdlodDetail* detail_ = nullptr;
    int width_ = 0, height_ = 0;
    int stored_level_ = 0;
    int levels_ = 0;
    std::vector<double> error_m_, max_error_m_;
    std::vector<double> diag_m_;           // the largest 3D box diagonal per level
    std::vector<int> nodes_x_, nodes_y_;
    std::vector<std::vector<Box>> boxes_;  // per level from stored_level_ up, row-major nodes
};

// delta of a mesh with a vertex every `spacing` texels (clamped to the last row and column,
// as the shader clamps) against the grid's heights: the `quantile` of |h - mesh| over all
// texels (1 = the largest; ranks as bench's percentile: the value of rank floor(q n)).
// Triangles split along the (0,0)-(1,1) diagonal of each quad, as the index buffer does.
double mesh_error_m(const terrain::HeightGrid& grid, int spacing, double quantile = 1.0);

// The eight corners' frustum test of a box given in eye-relative metres: false only when every
// corner is outside one clip plane.
bool box_in_frustum(const glm::dmat4& view_projection, const glm::dvec3& lo, const glm::dvec3& hi);

}  // namespace ts::fly
