#include "core/mesh/imported_scene.hpp"

#include <cstring>
#include <type_traits>

#include "core/util/error.hpp"

namespace ts::mesh {
namespace {

constexpr std::uint32_t kMagic = 0x54534d31;  // "TSM1"

class Writer {
public:
    template <typename T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        out.insert(out.end(), p, p + sizeof(T));
    }
    template <typename T>
    void put_array(const std::vector<T>& v) {
        put(std::uint64_t(v.size()));
        const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
        out.insert(out.end(), p, p + v.size() * sizeof(T));
    }
    void put_string(const std::string& s) {
        put(std::uint64_t(s.size()));
        out.insert(out.end(), s.begin(), s.end());
    }
    std::vector<std::uint8_t> out;
};

// Every read checks that the bytes hold it; a count is checked against the bytes left before
// anything is allocated for it.
class Reader {
public:
    Reader(const std::uint8_t* d, std::size_t n, const std::string& shown) : data_(d), size_(n), shown_(shown) {}

    template <typename T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T v;
        std::memcpy(&v, data_ + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }
    std::size_t count(std::size_t element_bytes) {
        const auto n = get<std::uint64_t>();
        if (element_bytes > 0 && n > (size_ - pos_) / element_bytes) fail();
        return std::size_t(n);
    }
    template <typename T>
    std::vector<T> get_array() {
        const std::size_t n = count(sizeof(T));
        std::vector<T> v(n);
        if (n) std::memcpy(v.data(), data_ + pos_, n * sizeof(T));
        pos_ += n * sizeof(T);
        return v;
    }
    std::string get_string() {
        const std::size_t n = count(1);
        std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        return s;
    }
    bool at_end() const { return pos_ == size_; }
    [[noreturn]] void fail() const { throw input_error(shown_, "the mesh reader returned a malformed result"); }

private:
    void need(std::size_t n) const {
        if (n > size_ - pos_) fail();
    }
    const std::uint8_t* data_;
    std::size_t size_, pos_ = 0;
    const std::string& shown_;
};

}  // namespace

std::vector<std::uint8_t> encode_scene(const ImportedScene& scene) {
    Writer w;
    w.put(kMagic);
    w.put(std::int32_t(scene.header_up_axis));
    w.put(std::int32_t(scene.header_up_sign));
    w.put(std::uint64_t(scene.nodes.size()));
    for (const ImportedNode& n : scene.nodes) {
        w.put(n.transform);
        w.put_array(n.meshes);
        w.put_array(n.children);
    }
    w.put(std::uint64_t(scene.meshes.size()));
    for (const ImportedMesh& m : scene.meshes) {
        w.put_array(m.vertices);
        w.put_array(m.normals);
        w.put_array(m.triangles);
        w.put(m.material);
    }
    w.put(std::uint64_t(scene.materials.size()));
    for (const MeshMaterial& m : scene.materials) {
        w.put_string(m.name);
        w.put(m.base_color);
        w.put_string(m.base_color_texture);
    }
    return std::move(w.out);
}

ImportedScene decode_scene(const std::uint8_t* data, std::size_t size, const std::string& shown) {
    Reader r(data, size, shown);
    if (r.get<std::uint32_t>() != kMagic) r.fail();
    ImportedScene s;
    s.header_up_axis = r.get<std::int32_t>();
    s.header_up_sign = r.get<std::int32_t>();
    if (s.header_up_axis < -1 || s.header_up_axis > 2 || (s.header_up_sign != 1 && s.header_up_sign != -1)) r.fail();
    // The smallest encoded node, mesh and material, to bound their counts by the bytes left.
    constexpr std::size_t kMinNode = sizeof(glm::dmat4) + 16, kMinMesh = 3 * 8 + 4, kMinMaterial = 16 + sizeof(glm::vec4);
    s.nodes.resize(r.count(kMinNode));
    for (ImportedNode& n : s.nodes) {
        n.transform = r.get<glm::dmat4>();
        n.meshes = r.get_array<std::uint32_t>();
        n.children = r.get_array<std::uint32_t>();
    }
    s.meshes.resize(r.count(kMinMesh));
    for (ImportedMesh& m : s.meshes) {
        m.vertices = r.get_array<glm::vec3>();
        m.normals = r.get_array<glm::vec3>();
        m.triangles = r.get_array<std::uint32_t>();
        m.material = r.get<std::uint32_t>();
        if (!m.normals.empty() && m.normals.size() != m.vertices.size()) r.fail();
        if (m.triangles.size() % 3 != 0) r.fail();
    }
    s.materials.resize(r.count(kMinMaterial));
    for (MeshMaterial& m : s.materials) {
        m.name = r.get_string();
        m.base_color = r.get<glm::vec4>();
        m.base_color_texture = r.get_string();
    }
    if (!r.at_end()) r.fail();
    return s;
}

}  // namespace ts::mesh
