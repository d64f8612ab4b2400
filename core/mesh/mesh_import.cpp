#include "core/mesh/mesh_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>

#include "core/mesh/imported_scene.hpp"
#include "core/mesh/scene_flattening.hpp"
#include "core/util/error.hpp"
#include "core/util/isolated_call.hpp"
#include "core/util/memory.hpp"

namespace ts::mesh {
namespace fs = std::filesystem;

namespace {
std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}
}  // namespace

bool is_animated_alternative(const std::string& name, const std::set<std::string>& names) {
    const std::string n = lower(name);
    // A propeller's blur disc (FlightGear's Propeller.Fast, PropDisc, ...).
    if (n.find("prop") != std::string::npos &&
        (n.ends_with(".fast") || n.find("disc") != std::string::npos || n.find("disk") != std::string::npos ||
         n.find("blur") != std::string::npos))
        return true;
    // A light's lit version beside its unlit one (BeaconOn / BeaconOff).
    return n.size() > 2 && n.ends_with("on") && names.contains(n.substr(0, n.size() - 2) + "off");
}

namespace {

// assimp's error strings may span lines; the user gets one.
std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

glm::dmat4 to_glm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
    return glm::dmat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

// The up axis the file's header declares (FBX: UpAxis 0/1/2, UpAxisSign +-1), if any.
bool header_up_axis(const aiScene& scene, UpAxis& up, int& sign) {
    if (!scene.mMetaData) return false;
    int axis = -1;
    if (!scene.mMetaData->Get("UpAxis", axis) || axis < 0 || axis > 2) return false;
    up = axis == 0 ? UpAxis::x : axis == 1 ? UpAxis::y : UpAxis::z;
    int s = 1;
    if (scene.mMetaData->Get("UpAxisSign", s)) sign = s < 0 ? -1 : 1;
    return true;
}

MeshMaterial read_material(const aiMaterial& m) {
    MeshMaterial out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    aiString tex;
    if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &tex) == AI_SUCCESS ||
        m.GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS)
        out.base_color_texture = tex.C_Str();
    aiColor4D c;
    if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
        out.base_color = glm::vec4(c.r, c.g, c.b, c.a);
        // glTF 1 and others give a texture instead of a colour and report black: the texture's
        // factor is then 1.
        if (!out.base_color_texture.empty() && c.r == 0 && c.g == 0 && c.b == 0) out.base_color = glm::vec4(1.0f);
    }
    float opacity = 1.0f;
    if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS) out.base_color.a = opacity;
    return out;
}

// The scene as plain data (imported_scene.hpp), in the child process: only polygons with three
// corners are kept (points and lines were sorted out, the rest triangulated).
ImportedScene record_scene(const aiScene& scene) {
    ImportedScene out;
    UpAxis up = UpAxis::automatic;
    int sign = 1;
    if (header_up_axis(scene, up, sign)) {
        out.header_up_axis = up == UpAxis::x ? 0 : up == UpAxis::y ? 1 : 2;
        out.header_up_sign = sign;
    }
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
        const aiMesh& me = *scene.mMeshes[i];
        ImportedMesh m;
        m.material = me.mMaterialIndex;
        m.vertices.reserve(me.mNumVertices);
        for (unsigned v = 0; v < me.mNumVertices; ++v)
            m.vertices.emplace_back(me.mVertices[v].x, me.mVertices[v].y, me.mVertices[v].z);
        if (me.mNormals)
            for (unsigned v = 0; v < me.mNumVertices; ++v)
                m.normals.emplace_back(me.mNormals[v].x, me.mNormals[v].y, me.mNormals[v].z);
        for (unsigned f = 0; f < me.mNumFaces; ++f) {
            const aiFace& face = me.mFaces[f];
            if (face.mNumIndices != 3) continue;
            m.triangles.insert(m.triangles.end(), face.mIndices, face.mIndices + 3);
        }
        out.meshes.push_back(std::move(m));
    }
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) out.materials.push_back(read_material(*scene.mMaterials[i]));
    // The node tree, breadth first: a node's children follow in order, so their indices count on.
    std::vector<const aiNode*> order{scene.mRootNode};
    for (std::size_t k = 0; k < order.size(); ++k)
        for (unsigned c = 0; c < order[k]->mNumChildren; ++c) order.push_back(order[k]->mChildren[c]);
    // Every node's name before any node is kept: a lit light is recognised by its unlit twin.
    std::set<std::string> names;
    for (const aiNode* n : order) names.insert(lower(n->mName.C_Str()));
    std::uint32_t next_child = 1;
    for (const aiNode* n : order) {
        ImportedNode node;
        node.transform = to_glm(n->mTransformation);
        if (!is_animated_alternative(n->mName.C_Str(), names)) node.meshes.assign(n->mMeshes, n->mMeshes + n->mNumMeshes);
        for (unsigned c = 0; c < n->mNumChildren; ++c) node.children.push_back(next_child++);
        out.nodes.push_back(std::move(node));
    }
    return out;
}

// In the child process: assimp reads the file; its scene comes back as bytes.
std::vector<std::uint8_t> read_with_assimp(const fs::path& file, const std::string& shown) {
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, true);  // FBX is in centimetres by default
    const aiScene* scene =
        importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
    if (!scene) {
        const std::string why = one_line(importer.GetErrorString());
        // The primitive-type sort removes point and line meshes and then complains of none left
        // (or the validation, of meshes without faces).
        if (why.find("No meshes remaining") != std::string::npos || why.find("contains no faces") != std::string::npos)
            throw input_error(shown, "no triangles (only points or lines)");
        throw input_error(shown, "not a readable mesh (" + why + ")");
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0) throw input_error(shown, "no triangles (no mesh in the file)");
    return encode_scene(record_scene(*scene));
}

}  // namespace

TriangleMesh import_mesh(const fs::path& file, const ImportOptions& options) {
    const std::string shown = file.string();
    std::error_code ec;
    if (!fs::exists(file, ec)) throw input_error(shown, "no such file");
    if (fs::is_directory(file, ec)) throw input_error(shown, "is a directory, expected a mesh file");
    if (fs::file_size(file, ec) == 0 || ec) throw input_error(shown, "empty file");
    if (!(options.unit_scale > 0.0) || !std::isfinite(options.unit_scale))
        throw input_error(shown, "unit scale must be a positive number");

    const std::uint64_t file_bytes = fs::file_size(file, ec);
    IsolationLimits limits;
    limits.timeout_s = options.timeout_s > 0 ? options.timeout_s : 10.0 + 2.0 * double(file_bytes) / 1e6;
    limits.extra_address_space_bytes =
        options.memory_bytes > 0 ? options.memory_bytes : (std::uint64_t(512) << 20) + 100 * file_bytes;
    limits.extra_address_space_bytes = std::min(limits.extra_address_space_bytes, available_memory());
    const std::vector<std::uint8_t> bytes = run_isolated([&] { return read_with_assimp(file, shown); }, shown, limits);
    const ImportedScene scene = decode_scene(bytes.data(), bytes.size(), shown);

    UpAxis up = options.up;
    int sign = 1;
    if (up == UpAxis::automatic) {
        if (scene.header_up_axis >= 0) {
            up = scene.header_up_axis == 0 ? UpAxis::x : scene.header_up_axis == 1 ? UpAxis::y : UpAxis::z;
            sign = scene.header_up_sign;
        } else {
            up = default_up_axis(file.extension().string());
        }
    }
    const glm::dmat4 root = glm::dmat4(to_z_up(up, sign)) * glm::dmat4(glm::dmat3(options.unit_scale));
    return flatten_scene(scene, root, shown);
}

}  // namespace ts::mesh
