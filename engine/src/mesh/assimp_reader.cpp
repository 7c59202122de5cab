// read_with_assimp: every format assimp reads, other than PLY and OBJ (our own readers).
//
// No post-processing at all: aiProcess_Triangulate rotates corners (even of triangles) and
// starts quads at a concave corner, aiProcess_JoinIdenticalVertices merges by position, and
// aiProcess_PreTransformVertices regroups meshes by material. We walk the node tree in
// order instead, append each referenced mesh's vertices and faces as assimp holds them,
// apply the node transforms (exactly nothing when they are identity, the usual case), and
// split polygons into fans ourselves. Points and lines are not triangles and are skipped.
// Whether vertices are shared is up to each assimp importer (OFF and PLY keep the file's
// vertices; STL has none to share; OBJ does not, hence our own reader); within each mesh we
// then weld vertices at the same position (mesh/weld.hpp), so the seams an importer splits for
// normals and texture coordinates are not reported as touching neighbours.

#include "mesh/assimp_checks.hpp"
#include "mesh/fan.hpp"
#include "mesh/weld.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <limits>

namespace collidescope {
namespace {

// Exact comparison: assimp's own IsIdentity() tolerates an epsilon.
bool is_identity(const aiMatrix4x4& m) {
    for (unsigned row = 0; row < 4; ++row) {
        for (unsigned col = 0; col < 4; ++col) {
            if (m[row][col] != (row == col ? 1.0f : 0.0f)) return false;
        }
    }
    return true;
}

Vec3 transformed(const aiMatrix4x4& m, const aiVector3D& v, bool identity) {
    const double x = v.x, y = v.y, z = v.z;
    if (identity) return {x, y, z};
    const auto row = [&](unsigned r) {
        return double{m[r][0]} * x + double{m[r][1]} * y + double{m[r][2]} * z + double{m[r][3]};
    };
    return {row(0), row(1), row(2)};
}

class SceneFlattener {
public:
    SceneFlattener(const aiScene& scene, const std::filesystem::path& file)
        : m_scene(scene), m_file(file) {}

    MeshData flatten() {
        if (m_scene.mRootNode != nullptr) {
            append_node(*m_scene.mRootNode, aiMatrix4x4());
        } else {
            for (unsigned m = 0; m < m_scene.mNumMeshes; ++m) append_mesh(m, aiMatrix4x4());
        }
        return std::move(m_mesh);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(m_file.string() + ": " + what);
    }

    void append_node(const aiNode& node, const aiMatrix4x4& parent) {
        const aiMatrix4x4 transform = parent * node.mTransformation;
        for (unsigned i = 0; i < node.mNumMeshes; ++i) append_mesh(node.mMeshes[i], transform);
        for (unsigned c = 0; c < node.mNumChildren; ++c) append_node(*node.mChildren[c], transform);
    }

    void append_mesh(unsigned index, const aiMatrix4x4& transform) {
        if (index >= m_scene.mNumMeshes) fail("node refers to missing mesh " + std::to_string(index));
        const aiMesh& mesh = *m_scene.mMeshes[index];
        const std::size_t offset = m_mesh.vertices.size();
        if (offset + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max()) {
            fail("too many vertices");
        }
        const bool identity = is_identity(transform);
        m_welding = weld_by_position(mesh);
        for (const std::uint32_t v : m_welding.kept) {
            m_mesh.vertices.push_back(transformed(transform, mesh.mVertices[v], identity));
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) append_face(mesh, index, f, offset);
    }

    // A static mesh is one frame: vertices that coincide there are one vertex.
    static Welding weld_by_position(const aiMesh& mesh) {
        WeldKeys keys;
        keys.values.reserve(3 * std::size_t{mesh.mNumVertices});
        keys.begin.reserve(std::size_t{mesh.mNumVertices} + 1);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            const double key[3] = {p.x, p.y, p.z};
            keys.add(key);
        }
        return weld(keys);
    }

    void append_face(const aiMesh& mesh, unsigned mesh_index, unsigned face_index, std::size_t offset) {
        const aiFace& face = mesh.mFaces[face_index];
        if (face.mNumIndices < 3) return;
        m_corners.resize(face.mNumIndices);
        for (unsigned c = 0; c < face.mNumIndices; ++c) {
            const unsigned corner = face.mIndices[c];
            if (corner >= mesh.mNumVertices) {
                fail("mesh " + std::to_string(mesh_index) + " face " + std::to_string(face_index) +
                     ": vertex index " + std::to_string(corner) + " out of range (" +
                     std::to_string(mesh.mNumVertices) + " vertices)");
            }
            m_corners[c] = static_cast<std::uint32_t>(offset + m_welding.remap[corner]);
        }
        append_fan(m_corners, m_mesh.triangles);
    }

    const aiScene& m_scene;
    const std::filesystem::path& m_file;
    MeshData m_mesh;
    std::vector<std::uint32_t> m_corners;
    Welding m_welding;  ///< of the mesh being appended
};

const aiScene* import_scene(Assimp::Importer& importer, const std::filesystem::path& file) {
    if (file.extension() == ".gz") {
        // Gunzip ourselves and name the inner format by its extension (cube.off.gz -> "off").
        const std::vector<std::byte> bytes = read_file_bytes(file);
        std::string hint = file.stem().extension().string();
        if (!hint.empty()) hint.erase(0, 1);
        return importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, hint.c_str());
    }
    std::error_code error;
    const auto status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status)) throw InputError(file.string() + ": no such file");
    if (std::filesystem::is_directory(status)) {
        throw InputError(file.string() + ": is a directory, not a file");
    }
    return importer.ReadFile(file.string(), 0);
}

}  // namespace

const aiScene& import_checked(Assimp::Importer& importer, const std::filesystem::path& file) {
    check_counts_fit(file);
    const aiScene* scene = nullptr;
    {
        const QuietCerr quiet;
        scene = import_scene(importer, file);
    }
    if (scene == nullptr) {
        throw InputError(file.string() + ": assimp cannot read it (" + importer.GetErrorString() + ")");
    }
    validate_assimp_scene(*scene, file);
    return *scene;
}

MeshData read_with_assimp(const std::filesystem::path& file) {
    Assimp::Importer importer;
    return SceneFlattener(import_checked(importer, file), file).flatten();
}

}  // namespace collidescope
