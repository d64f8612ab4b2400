#include "core/mesh/mesh_import.hpp"

#include <cmath>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/util/error.hpp"

namespace ts::mesh {
namespace fs = std::filesystem;

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

struct Walk {
    const aiScene& scene;
    glm::dmat4 root;  // axis and unit normalisation
    TriangleMesh& out;

    void node(const aiNode& n, const glm::dmat4& parent) {
        const glm::dmat4 m = parent * to_glm(n.mTransformation);
        // Normals go through the inverse transpose (non-uniform scales in real node graphs).
        const glm::dmat3 normal_m = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (unsigned i = 0; i < n.mNumMeshes; ++i) mesh(*scene.mMeshes[n.mMeshes[i]], m, normal_m);
        for (unsigned c = 0; c < n.mNumChildren; ++c) node(*n.mChildren[c], m);
    }

    void mesh(const aiMesh& me, const glm::dmat4& m, const glm::dmat3& normal_m) {
        for (unsigned f = 0; f < me.mNumFaces; ++f) {
            const aiFace& face = me.mFaces[f];
            if (face.mNumIndices != 3) continue;
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                const aiVector3D& v = me.mVertices[face.mIndices[k]];
                p[k] = glm::vec3(m * glm::dvec4(v.x, v.y, v.z, 1.0));
            }
            glm::dvec3 face_n = glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0]));
            const double len = glm::length(face_n);
            face_n = len > 0 ? face_n / len : glm::dvec3(0, 0, 1);
            for (int k = 0; k < 3; ++k) {
                if (!std::isfinite(p[k].x) || !std::isfinite(p[k].y) || !std::isfinite(p[k].z)) continue;
                glm::dvec3 nk = face_n;
                if (me.mNormals) {
                    const aiVector3D& v = me.mNormals[face.mIndices[k]];
                    const glm::dvec3 t = normal_m * glm::dvec3(v.x, v.y, v.z);
                    const double tl = glm::length(t);
                    if (tl > 0 && std::isfinite(tl)) nk = t / tl;
                }
                out.positions.push_back(p[k]);
                out.normals.push_back(glm::vec3(nk));
            }
            // A corner that was not finite drops the whole triangle.
            const std::size_t extra = out.positions.size() % 3;
            if (extra != 0) {
                out.positions.resize(out.positions.size() - extra);
                out.normals.resize(out.normals.size() - extra);
                continue;
            }
            out.material.push_back(me.mMaterialIndex);
        }
    }
};

}  // namespace

TriangleMesh import_mesh(const fs::path& file, const ImportOptions& options) {
    const std::string shown = file.string();
    std::error_code ec;
    if (!fs::exists(file, ec)) throw input_error(shown, "no such file");
    if (fs::is_directory(file, ec)) throw input_error(shown, "is a directory, expected a mesh file");
    if (fs::file_size(file, ec) == 0 || ec) throw input_error(shown, "empty file");
    if (!(options.unit_scale > 0.0) || !std::isfinite(options.unit_scale))
        throw input_error(shown, "unit scale must be a positive number");

    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, true);  // FBX is in centimetres by default
    const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_SortByPType);
    if (!scene) {
        const std::string why = one_line(importer.GetErrorString());
        // The primitive-type sort removes point and line meshes and then complains of none left.
        if (why.find("No meshes remaining") != std::string::npos)
            throw input_error(shown, "no triangles (only points or lines)");
        throw input_error(shown, "not a readable mesh (" + why + ")");
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0) throw input_error(shown, "no triangles (no mesh in the file)");

    UpAxis up = options.up;
    int sign = 1;
    if (up == UpAxis::automatic && !header_up_axis(*scene, up, sign)) up = default_up_axis(file.extension().string());
    const glm::dmat4 root = glm::dmat4(to_z_up(up, sign)) * glm::dmat4(glm::dmat3(options.unit_scale));

    TriangleMesh out;
    Walk{*scene, root, out}.node(*scene->mRootNode, root);
    if (out.triangle_count() == 0) throw input_error(shown, "no triangles");
    for (unsigned i = 0; i < scene->mNumMaterials; ++i) out.materials.push_back(read_material(*scene->mMaterials[i]));
    if (out.materials.empty()) out.materials.push_back(MeshMaterial{"default"});
    for (std::uint32_t& m : out.material)
        if (m >= out.materials.size()) m = 0;
    return out;
}

}  // namespace ts::mesh
