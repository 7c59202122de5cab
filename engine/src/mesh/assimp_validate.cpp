// validate_assimp_scene: what assimp returned, checked before anything walks it.
//
// Only what the readers follow is checked (not assimp's full aiProcess_ValidateDataStructure,
// which also refuses scenes for things we never read: on assimp-testmodels it refuses a
// light without a node and an empty STL solid, files that load fine here). A count with a
// null array, a null element, a node mesh index out of range or a node reached twice (a
// cycle or a shared child) is an error naming the element.

#include "mesh/assimp_checks.hpp"

#include "collidescope/error.hpp"

#include <assimp/scene.h>

#include <string>
#include <unordered_set>
#include <vector>

namespace collidescope {
namespace {

class SceneValidator {
public:
    SceneValidator(const aiScene& scene, const std::filesystem::path& file) : m_scene(scene), m_file(file) {}

    void validate() {
        check_array(m_scene.mMeshes, m_scene.mNumMeshes, "scene", "meshes");
        for (unsigned m = 0; m < m_scene.mNumMeshes; ++m) check_mesh(m);
        check_array(m_scene.mAnimations, m_scene.mNumAnimations, "scene", "animations");
        for (unsigned a = 0; a < m_scene.mNumAnimations; ++a) check_animation(a);
        if (m_scene.mRootNode != nullptr) check_nodes(*m_scene.mRootNode);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(m_file.string() + ": assimp returned a broken scene: " + what);
    }

    // `count` elements at `array`, none of them null when they are pointers.
    template <class T>
    void check_array(T* const* array, unsigned count, const std::string& owner, const char* what) const {
        if (count == 0) return;
        check_values(array, count, owner, what);
        for (unsigned i = 0; i < count; ++i) {
            if (array[i] != nullptr) continue;
            fail(owner + ": " + what + " " + std::to_string(i) + " of " + std::to_string(count) + " is null");
        }
    }
    template <class T>
    void check_values(const T* array, unsigned count, const std::string& owner, const char* what) const {
        if (count == 0 || array != nullptr) return;
        fail(owner + " has " + std::to_string(count) + " " + what + " but no array of them");
    }

    static std::string named(const char* kind, unsigned index, const aiString& name) {
        std::string text = std::string(kind) + " " + std::to_string(index);
        if (name.length > 0) text += " '" + std::string(name.C_Str()) + "'";
        return text;
    }

    void check_mesh(unsigned index) const {
        const aiMesh& mesh = *m_scene.mMeshes[index];
        const std::string owner = named("mesh", index, mesh.mName);
        check_values(mesh.mVertices, mesh.mNumVertices, owner, "vertices");
        check_values(mesh.mFaces, mesh.mNumFaces, owner, "faces");
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            check_values(face.mIndices, face.mNumIndices, owner + " face " + std::to_string(f), "corners");
        }
        check_array(mesh.mBones, mesh.mNumBones, owner, "bones");
        for (unsigned b = 0; b < mesh.mNumBones; ++b) {
            const aiBone& bone = *mesh.mBones[b];
            check_values(bone.mWeights, bone.mNumWeights, owner + " " + named("bone", b, bone.mName), "weights");
        }
        check_array(mesh.mAnimMeshes, mesh.mNumAnimMeshes, owner, "morph targets");
        for (unsigned t = 0; t < mesh.mNumAnimMeshes; ++t) {
            const aiAnimMesh& target = *mesh.mAnimMeshes[t];
            if (target.mNumVertices != 0 && target.mVertices == nullptr) {
                fail(owner + " morph target " + std::to_string(t) + " has no vertices array");
            }
        }
    }

    void check_animation(unsigned index) const {
        const aiAnimation& animation = *m_scene.mAnimations[index];
        const std::string owner = named("animation", index, animation.mName);
        check_array(animation.mChannels, animation.mNumChannels, owner, "node channels");
        for (unsigned c = 0; c < animation.mNumChannels; ++c) {
            const aiNodeAnim& channel = *animation.mChannels[c];
            const std::string where = owner + " " + named("node channel", c, channel.mNodeName);
            check_values(channel.mPositionKeys, channel.mNumPositionKeys, where, "position keys");
            check_values(channel.mRotationKeys, channel.mNumRotationKeys, where, "rotation keys");
            check_values(channel.mScalingKeys, channel.mNumScalingKeys, where, "scaling keys");
        }
        check_array(animation.mMeshChannels, animation.mNumMeshChannels, owner, "mesh channels");
        for (unsigned c = 0; c < animation.mNumMeshChannels; ++c) {
            const aiMeshAnim& channel = *animation.mMeshChannels[c];
            const std::string where = owner + " " + named("mesh channel", c, channel.mName);
            check_values(channel.mKeys, channel.mNumKeys, where, "keys");
        }
        check_array(animation.mMorphMeshChannels, animation.mNumMorphMeshChannels, owner, "morph channels");
        for (unsigned c = 0; c < animation.mNumMorphMeshChannels; ++c) {
            const aiMeshMorphAnim& channel = *animation.mMorphMeshChannels[c];
            const std::string where = owner + " " + named("morph channel", c, channel.mName);
            check_values(channel.mKeys, channel.mNumKeys, where, "keys");
            for (unsigned k = 0; k < channel.mNumKeys; ++k) {
                const aiMeshMorphKey& key = channel.mKeys[k];
                const std::string key_where = where + " key " + std::to_string(k);
                check_values(key.mValues, key.mNumValuesAndWeights, key_where, "values");
                check_values(key.mWeights, key.mNumValuesAndWeights, key_where, "weights");
            }
        }
    }

    // Depth first with an explicit stack: a deep or cyclic graph must not overflow ours.
    void check_nodes(const aiNode& root) {
        std::vector<const aiNode*> stack{&root};
        while (!stack.empty()) {
            const aiNode& node = *stack.back();
            stack.pop_back();
            const std::string owner = "node '" + std::string(node.mName.C_Str()) + "'";
            if (!m_seen.insert(&node).second) fail(owner + " is reached twice (the node graph is not a tree)");
            check_values(node.mMeshes, node.mNumMeshes, owner, "mesh references");
            for (unsigned i = 0; i < node.mNumMeshes; ++i) {
                if (node.mMeshes[i] >= m_scene.mNumMeshes) {
                    fail(owner + " refers to mesh " + std::to_string(node.mMeshes[i]) + " (the scene has " +
                         std::to_string(m_scene.mNumMeshes) + ")");
                }
            }
            check_array(node.mChildren, node.mNumChildren, owner, "children");
            for (unsigned c = node.mNumChildren; c-- > 0;) stack.push_back(node.mChildren[c]);
        }
    }

    const aiScene& m_scene;
    const std::filesystem::path& m_file;
    std::unordered_set<const aiNode*> m_seen;
};

}  // namespace

void validate_assimp_scene(const aiScene& scene, const std::filesystem::path& file) {
    SceneValidator(scene, file).validate();
}

}  // namespace collidescope
