#include "tests/fuzz/mesh_fuzz_inputs.hpp"

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string_view>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "core/mesh/imported_scene.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/scene_flattening.hpp"
#include "core/util/error.hpp"

namespace ts::fuzz {
namespace fs = std::filesystem;
namespace {

constexpr const char* kExtensions[] = {".obj", ".stl", ".ply", ".off", ".ac", ".gltf", ".glb", ".dae", ".3ds", ".fbx"};

template <typename F>
MeshOutcome outcome_of(F&& f, std::string* message = nullptr) {
    try {
        f();
        return MeshOutcome::read;
    } catch (const InputError& e) {
        if (message) *message = e.what();
        return MeshOutcome::input_error;
    }
}

// Inputs that crashed or hung the parser in its child process are handled (one error), but
// worth keeping as regression inputs: with TS_FUZZ_ISOLATED_DIR set, each is copied there.
void keep_if_isolated_failure(const std::string& message, const std::uint8_t* data, std::size_t size) {
    const char* dir = std::getenv("TS_FUZZ_ISOLATED_DIR");
    if (!dir || (message.find("crashed") == std::string::npos && message.find("did not finish") == std::string::npos))
        return;
    fs::create_directories(dir);
    const fs::path p = fs::path(dir) / ("isolated-" + std::to_string(::getpid()) + "-" + std::to_string(size) + "-" +
                                        std::to_string(std::hash<std::string_view>{}(
                                            std::string_view(reinterpret_cast<const char*>(data), size))));
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

}  // namespace

const char* mesh_extension(std::uint8_t selector) {
    return kExtensions[selector % (sizeof kExtensions / sizeof kExtensions[0])];
}

MeshOutcome feed_mesh_file(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return MeshOutcome::input_error;
    const fs::path dir = fs::temp_directory_path() / ("ts_mesh_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path path = dir / (std::string("input") + mesh_extension(data[0]));
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    mesh::ImportOptions options;
    options.timeout_s = 5;  // a parser looping on a mutated file is reported, not waited for
    std::string message;
    const MeshOutcome result = outcome_of([&] { mesh::import_mesh(path, options); }, &message);
    keep_if_isolated_failure(message, data, size);
    std::error_code ec;
    fs::remove(path, ec);
    return result;
}

MeshOutcome feed_mesh_scene(const std::uint8_t* data, std::size_t size) {
    return outcome_of([&] {
        const mesh::ImportedScene s = mesh::decode_scene(data, size, "scene");
        mesh::flatten_scene(s, glm::dmat4(1.0), "scene");
    });
}

MeshFeed mesh_feed_for(const std::string& target) {
    if (target == "mesh_file") return feed_mesh_file;
    if (target == "mesh_scene") return feed_mesh_scene;
    return nullptr;
}

}  // namespace ts::fuzz
