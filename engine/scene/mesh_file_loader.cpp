// engine/scene/mesh_file_loader.cpp — OBJ and PLY meshes through Assimp, and load_model.
//
// Research scans come as OBJ and PLY (rtsc reads both). Assimp (Debian's libassimp-dev) parses
// them: OBJ with its groups and polygons, PLY in ASCII and both binary byte orders. It gives
// per-corner vertices for OBJ; JoinIdenticalVertices merges the corners that agree in every
// attribute, numbered in order of first use. The triangles are a glTF's when the file holds
// the same ones, and the line stages number vertices by first use too (geometry/welded_mesh),
// so the vertex order does not change the picture. Points and lines are dropped (as
// load_gltf skips them), polygons become triangles. Then every primitive passes the checks a
// glTF primitive passes: indices in range, finite positions and normals. Assimp 5.2 trusts
// what a PLY declares (hangs, aborts, fills memory on malformed files): scene/ply_check.cpp
// checks the structure first, and our own pass over the faces runs before its post-processing.
#include <cmath>
#include <string>
#include <utility>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/error.h"
#include "core/text.h"
#include "scene/model.h"
#include "scene/ply_check.h"

namespace lw {

namespace {

constexpr unsigned kMaxPolygonCorners = 1024;
constexpr const char* kNoTriangles = "no triangles (the file has no faces, or only points and lines)";

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::vec3 to_glm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// Assimp gives a file without materials (a PLY, an OBJ without .mtl) a stand-in one; its
// meshes have no material, as a glTF primitive without one (-1).
bool is_stand_in(const aiMaterial& material) {
    aiString name;
    material.Get(AI_MATKEY_NAME, name);
    return std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME;
}

// The material's name, "" for the stand-in (as for an unnamed glTF material).
std::string material_name(const aiMaterial& material) {
    aiString name;
    material.Get(AI_MATKEY_NAME, name);
    return is_stand_in(material) ? std::string() : std::string(name.C_Str());
}

// One Assimp mesh as a primitive; `label` names it in errors ("mesh 2").
Primitive to_primitive(const aiScene& scene, const aiMesh& mesh, const std::string& file, const std::string& label) {
    Primitive p;
    const bool has_material = mesh.mMaterialIndex < scene.mNumMaterials;
    p.material = has_material && !is_stand_in(*scene.mMaterials[mesh.mMaterialIndex]) ? int(mesh.mMaterialIndex) : -1;
    p.positions.reserve(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        if (!finite(mesh.mVertices[v]))
            throw Error(file + ": " + label + ": vertex " + std::to_string(v) + " has a position that is not finite");
        p.positions.push_back(to_glm(mesh.mVertices[v]));
    }
    if (mesh.mNormals) {
        p.normals.reserve(mesh.mNumVertices);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            if (!finite(mesh.mNormals[v]))
                throw Error(file + ": " + label + ": vertex " + std::to_string(v) + " has a normal that is not finite");
            p.normals.push_back(to_glm(mesh.mNormals[v]));
        }
    }
    p.indices.reserve(size_t(mesh.mNumFaces) * 3);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;  // a point or line Assimp left in a mixed mesh
        for (unsigned c = 0; c < 3; ++c) {
            if (face.mIndices[c] >= mesh.mNumVertices)
                throw Error(file + ": " + label + ": face " + std::to_string(f) + " refers to vertex " +
                            std::to_string(face.mIndices[c]) + " of " + std::to_string(mesh.mNumVertices));
            p.indices.push_back(face.mIndices[c]);
        }
    }
    return p;
}

// Drops the points and lines (as load_gltf skips them) and sets the mesh's primitive types
// from the faces it keeps, which the post-processing steps trust. The faces' storage is
// Assimp's (delete[] frees every element, kept or not). Returns the faces kept.
size_t keep_polygons(aiMesh& mesh, const std::string& file) {
    unsigned kept = 0;
    bool polygons = false;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        if (mesh.mFaces[f].mNumIndices < 3) continue;
        // Assimp's ear cutting is quadratic to cubic in a polygon's corners: a file of a few
        // huge polygons would take minutes. Scans have triangles and quads.
        if (mesh.mFaces[f].mNumIndices > kMaxPolygonCorners)
            throw Error(file + ": face " + std::to_string(f) + " has " + std::to_string(mesh.mFaces[f].mNumIndices) +
                        " corners (at most 1024 are read)");
        polygons |= mesh.mFaces[f].mNumIndices > 3;
        if (kept != f) std::swap(mesh.mFaces[kept], mesh.mFaces[f]);
        ++kept;
    }
    mesh.mNumFaces = kept;
    unsigned types = kept == 0 ? 0u : unsigned(aiPrimitiveType_TRIANGLE);
    if (polygons) types |= unsigned(aiPrimitiveType_POLYGON);
    mesh.mPrimitiveTypes = types;
    return kept;
}

// One mesh of one primitive, no material, under one root node: what an OBJ or PLY becomes.
Model single_mesh_model(const std::filesystem::path& path, std::vector<Primitive> primitives) {
    Model model;
    model.path = path;
    model.meshes.push_back(Mesh{.name = path.stem().string(), .primitives = std::move(primitives)});
    // OBJ and PLY have no scene graph worth keeping (OBJ groups are meshes here): one root node.
    model.nodes.push_back({.name = path.stem().string(), .mesh = 0});
    model.roots = {0};
    return model;
}

// A PLY of triangle strips (read_ply_strips has checked its indices and coordinates).
Model model_from_strips(PlyStripMesh strips, const std::filesystem::path& path) {
    if (strips.indices.empty()) throw Error(path.string() + ": " + kNoTriangles);
    Primitive p;
    p.positions = std::move(strips.positions);
    p.normals = std::move(strips.normals);
    p.indices = std::move(strips.indices);
    return single_mesh_model(path, {std::move(p)});
}

}  // namespace

bool is_mesh_file_path(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    return ext == ".obj" || ext == ".ply";
}

Model load_mesh_file(const std::filesystem::path& path) {
    const std::string file = path.string();
    if (!is_mesh_file_path(path))
        throw Error(file + ": unsupported file extension" + extension_phrase(lower(path.extension().string())) +
                    " (expected .obj or .ply)");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(file + ": no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(file + ": not a regular file");
    if (lower(path.extension().string()) == ".ply") {
        if (check_ply_structure(path, file)) return model_from_strips(read_ply_strips(path, file), path);
    }

    // Parsed and validated first, post-processed after our own pass over the faces: Debian's
    // Assimp is built with its assertions on, and its Triangulate step aborts the process on
    // a mesh whose primitive types the PLY reader got wrong (found by tests/fuzz/fuzz_mesh).
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
    if (!scene) {
        const std::string reason = one_line(importer.GetErrorString());
        // A PLY point cloud fails Assimp's validation as "Mesh  contains no faces".
        if (reason.find("contains no faces") != std::string::npos) throw Error(file + ": " + kNoTriangles);
        throw Error(file + ": cannot load the mesh: " + (reason.empty() ? "Assimp gave no reason" : reason));
    }
    size_t faces = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) faces += keep_polygons(*scene->mMeshes[m], file);
    if (faces == 0) throw Error(file + ": " + kNoTriangles);
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (!scene) throw Error(file + ": cannot load the mesh: " + one_line(importer.GetErrorString()));

    std::vector<Primitive> primitives;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        Primitive p = to_primitive(*scene, *scene->mMeshes[m], file, "mesh " + std::to_string(m));
        if (!p.indices.empty()) primitives.push_back(std::move(p));
    }
    if (primitives.empty()) throw Error(file + ": " + kNoTriangles);
    Model model = single_mesh_model(path, std::move(primitives));
    // Names only: line sets select by them; the scene colours the surface (MTL colours are not read).
    for (unsigned m = 0; m < scene->mNumMaterials; ++m)
        model.materials.push_back(Material{.name = material_name(*scene->mMaterials[m]), .has_color = false});
    return model;
}

Model load_model(const std::filesystem::path& path) {
    return is_mesh_file_path(path) ? load_mesh_file(path) : load_gltf(path);
}

}  // namespace lw
