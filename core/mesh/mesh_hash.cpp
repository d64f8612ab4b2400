#include "core/mesh/mesh_hash.hpp"

#include <cstdio>
#include <cstring>

namespace ts::mesh {

std::uint64_t geometry_hash(const TriangleMesh& mesh) {
    // FNV-1a over 8-byte words (the bytes of the float positions), then a final avalanche
    // (splitmix64) so nearby meshes land far apart.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](std::uint64_t w) {
        h ^= w;
        h *= 1099511628211ull;
    };
    mix(mesh.triangle_count());
    const auto* bytes = reinterpret_cast<const unsigned char*>(mesh.positions.data());
    const std::size_t size = mesh.positions.size() * sizeof(glm::vec3);
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, bytes + i, 8);
        mix(w);
    }
    for (; i < size; ++i) mix(bytes[i]);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebull;
    h ^= h >> 31;
    return h;
}

std::string hash_hex(std::uint64_t hash) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

}  // namespace ts::mesh
