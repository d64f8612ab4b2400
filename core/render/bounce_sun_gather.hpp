#pragma once
// The bounced light's sun part, gathered each frame from the light the neighbours really get
// (docs/rendering.md, "Bounced light"). The terrain t sees below its horizons reflects, in the
// sun, B_j = albedo_j E_sun max(0, n_j . s) V_j / pi, V_j the visible share of the sun's disc
// (the frame's own sun shadows, the meshes' too). Through T_b's SH (BounceSettings::SunPart::sh)
// the neighbours' sun is <T_j, Y(s)> over bands 0..1: smooth, blind to their cast shadows, so a
// valley in shadow got its lit slopes' bounce; against Blender Cycles that was most of the
// bounce's error inside cast shadows. Here the sum is made again per frame with the gather's
// own weights (core/visibility/terrain_gather.hpp, recorded once with T_b):
//   b1_t = sum_j w_tj sun_j + far_t max(0, s_z)      (units of E_sun / pi, as V_t max(0, n_t . s))
//   b2_t = sum_j w_tj b1_j                           (the second bounce, with --bounces 2)
// w_tj = (2 / sectors) x the gather's weight x albedo_j, far_t the blocked view the gather did not
// reach over pi x albedo_t (open flat ground, in the sun), sun_j = max(0, n_j . s) V_j.
//
// Kept by runs of 8 receivers along a row (a "chunk"): the gather marches the same steps from
// every receiver of a row, so neighbours see their terrain at the same offsets j - t. A chunk
// lists the offsets any of its 8 receivers sees, each with 8 weights (0 where a receiver does
// not see it). Per frame one offset is then 8 contiguous values times 8 weights, a vector
// multiply-add with no per-receiver gather. A weight is 8 bits against its receiver's largest,
// each rounding carried into the next: the bounce within ~1e-3 of its own, for 84 bytes a texel
// (docs/rendering.md, "How the weights are kept").
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ts::render {

// The gather reaches at most this many texels from its receiver (BounceSettings checks it).
inline constexpr int kBounceSunGatherReach = 126;

class BounceSunGather {
public:
    static constexpr int kLanes = 8;  // receivers per chunk

    // The values apply() reads, with a margin (lanes of a chunk read offsets only their
    // neighbours see, up to the reach beyond the grid) and the first bounce between the two.
    struct Scratch {
        std::vector<float> values, first;
        std::size_t texels = 0, margin = 0;  // their layout
    };

    BounceSunGather() = default;
    // Empty weights for a width x height grid (bounces 1 or 2).
    BounceSunGather(int bounces, int width, int height);

    // Receivers added in order of column along each row, rows in any order, from one thread
    // (threads each with their own writer take whole rows). finish() stores the last row: a
    // writer left without it (an exception) leaves that row without weights.
    class Writer {
    public:
        explicit Writer(BounceSunGather& g);
        Writer(const Writer&) = delete;
        Writer& operator=(const Writer&) = delete;
        // Receiver (col, row)'s terrain: grid indices and weights w_tj, and far_t. Receivers
        // left out get none. Throws std::logic_error on a texel beyond kBounceSunGatherReach.
        void add(int col, int row, const std::vector<std::uint32_t>& texel, const std::vector<float>& weight,
                 float far);
        void add_far(int col, int row, float far);  // a receiver that sees no terrain
        // A whole chunk at once (receivers col0 + l with bit l of `lanes` set; col0 a multiple
        // of kLanes), from the entries its receivers share: entry (dc, dr) from each receiver
        // with its weight per lane (0 where a lane does not see it). The same weights as add()
        // per receiver; a chunk is added whole this way or receiver by receiver, not both.
        struct ChunkEntry {
            int dc, dr;
            float weight[kLanes];
        };
        void add_chunk(int col0, int row, unsigned lanes, const ChunkEntry* entries, std::size_t count,
                       const float* far);
        void finish();

    private:
        void start(int row, int chunk);
        void flush();        // the chunk being filled by add() into the row's buffers
        void store_chunk();  // keys_ and sums_ (the chunk's offsets and weights) into the row's buffers
        BounceSunGather& g_;
        int row_ = -1, chunk_ = -1;
        std::vector<int> key_[kLanes];  // per receiver of the chunk, its entries' (dc, dr) as one index
        std::vector<float> weight_[kLanes];
        std::vector<std::uint32_t> slot_of_, stamp_;  // per (dc, dr): its place in the chunk, and when set
        std::uint32_t epoch_ = 0;
        std::vector<int> keys_;
        std::vector<float> sums_;
        std::vector<std::int32_t> offset_;  // the row's, as Row's
        std::vector<std::uint8_t> weight8_;
        std::vector<std::uint32_t> begin_;
        long long reach_ = 0;
    };

    int bounces() const { return bounces_; }
    int width() const { return width_; }
    bool empty() const { return far_.empty(); }
    std::size_t texels() const { return far_.size(); }
    std::size_t entries() const;  // receiver-offset pairs with a weight
    std::size_t slots() const;    // chunk offsets (x 8 weights each)
    const std::vector<float>& far() const { return far_; }

    // Where a frame writes sun_j, texels() finite values, for apply(): inside `scratch`, between
    // the margins it needs (the frame renderer fills it in place, no copy).
    float* sun_values(Scratch& scratch) const;
    // out[t] = b1_t (+ b2_t), texels() entries, from the values written through sun_values();
    // `sun_z` is the sun direction's up component. `vector_units`: false takes the portable loop
    // (the same sums; tests compare the two).
    void apply(float sun_z, float* out, Scratch& scratch, int threads, bool vector_units = true) const;
    // The same from an array of sun_j (NaN taken as 0), copied into `scratch` first.
    void apply(const float* sun, float sun_z, float* out, Scratch& scratch, int threads,
               bool vector_units = true) const;

private:
    struct Row {
        std::vector<std::uint32_t> chunk_begin;  // per chunk, where its offsets start; one more at the end
        std::vector<std::int32_t> offset;        // j - t, a grid index difference
        std::vector<std::uint8_t> weight;        // kLanes per offset: w_tj / scale_t in 8 bits
        long long reach = 0;                     // the largest |offset|
    };
    void gather_rows(const float* values, const float* base, float base_scale, float* out, int r0, int r1,
                     bool vector_units) const;

    int bounces_ = 0;
    int width_ = 0;
    std::vector<Row> rows_;
    std::vector<float> scale_;  // per texel: w_tj = weight x scale_t (its largest / 255)
    std::vector<float> far_;    // far_t (0 on voids)
};

}  // namespace ts::render
