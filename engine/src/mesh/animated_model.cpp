// read_animated_model: an aiScene (no post-processing) -> AnimatedModel.
//
// The node tree is walked depth-first (parents first, children in file order); each node's
// meshes become instances in the node's order. Faces with fewer than three corners (points,
// lines) are skipped and polygons split as fans, as read_with_assimp does; an instance left
// without triangles is not an object. Each instance is welded (weld.hpp) on the key
// (rest position, morph target positions, normalised influences).

#include "mesh/format_extension.hpp"
#include "mesh/animated_model.hpp"
#include "mesh/assimp_checks.hpp"

#include "mesh/fan.hpp"

#include "collidescope/error.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace collidescope::animation {
namespace {

Affine to_affine(const aiMatrix4x4& m) {
    Affine a;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) a(r, c) = m[r][c];
    }
    return a;
}

Vec3 to_vec(const aiVector3D& v) { return {v.x, v.y, v.z}; }

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

class ModelReader {
public:
    ModelReader(const aiScene& scene, const std::filesystem::path& file) : m_scene(scene), m_file(file) {}

    AnimatedModel read(bool only_if_animated) {
        read_up_axis();
        if (only_if_animated && m_scene.mNumAnimations == 0) return std::move(m_model);
        if (m_scene.mRootNode == nullptr) fail("the scene has no root node");
        read_nodes();
        for (std::uint32_t n = 0; n < m_model.nodes.size(); ++n) read_node_meshes(n);
        if (m_model.instances.empty()) fail("no triangles (no mesh with a face of three or more corners)");
        for (unsigned a = 0; a < m_scene.mNumAnimations; ++a) read_clip(a);
        check_morph_targets();
        return std::move(m_model);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw InputError(m_file.string() + ": " + what); }

    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "'" + std::string + "'".
    static std::string quoted(const aiString& name) {
        std::string text(1, '\'');
        text.append(name.C_Str()).push_back('\'');
        return text;
    }

    // Depth-first with an explicit stack (deep skeletons do not grow the call stack).
    void read_nodes() {
        std::vector<std::pair<const aiNode*, std::int32_t>> stack{{m_scene.mRootNode, -1}};
        std::unordered_set<const aiNode*> visited;
        while (!stack.empty()) {
            const auto [node, parent] = stack.back();
            stack.pop_back();
            if (node == nullptr) fail("node tree holds a null node");
            if ((node->mNumChildren > 0 && node->mChildren == nullptr) || (node->mNumMeshes > 0 && node->mMeshes == nullptr)) {
                fail("node " + quoted(node->mName) + ": children or mesh list missing");
            }
            if (!visited.insert(node).second) fail("node " + quoted(node->mName) + " appears twice in the node tree");
            const auto index = static_cast<std::int32_t>(m_model.nodes.size());
            m_model.nodes.push_back({node->mName.C_Str(), parent, to_affine(node->mTransformation)});
            m_ai_nodes.push_back(node);
            m_node_index.emplace(node->mName.C_Str(), static_cast<std::uint32_t>(index));  // first wins
            for (unsigned c = node->mNumChildren; c-- > 0;) stack.push_back({node->mChildren[c], index});
        }
    }

    void read_up_axis() {
        const std::string extension = lowercase(m_file.extension().string());
        if (extension == ".gltf" || extension == ".glb") m_model.up_axis = 'y';  // glTF 2.0, 3.4
        // FBX: assimp puts the file's GlobalSettings UpAxis on the scene's metadata (some
        // importers on the root node's). Its sign (UpAxisSign) is not kept.
        for (const aiMetadata* meta : {m_scene.mMetaData, m_scene.mRootNode == nullptr ? nullptr : m_scene.mRootNode->mMetaData}) {
            std::int32_t axis = -1;
            if (meta != nullptr && meta->Get("UpAxis", axis) && axis >= 0 && axis <= 2) {
                m_model.up_axis = "xyz"[axis];
                return;
            }
        }
    }

    void read_node_meshes(std::uint32_t n) {
        const aiNode& node = *m_ai_nodes[n];
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const unsigned mesh = node.mMeshes[i];
            if (mesh >= m_scene.mNumMeshes || m_scene.mMeshes[mesh] == nullptr) {
                fail("node " + quoted(node.mName) + " refers to missing mesh " + std::to_string(mesh));
            }
            MeshInstance instance = read_instance(n, mesh);
            if (!instance.triangles.empty()) m_model.instances.push_back(std::move(instance));
        }
    }

    std::string mesh_label(unsigned index) const {
        const aiString& name = m_scene.mMeshes[index]->mName;
        return "mesh " + std::to_string(index) + (name.length == 0 ? "" : " " + quoted(name));
    }

    MeshInstance read_instance(std::uint32_t node, unsigned index) {
        const aiMesh& mesh = *m_scene.mMeshes[index];
        MeshInstance instance;
        const std::string node_name = m_model.nodes[node].name.empty() ? "node" + std::to_string(node)
                                                                       : m_model.nodes[node].name;
        const std::string mesh_name = mesh.mName.length == 0 ? "mesh" + std::to_string(index) : mesh.mName.C_Str();
        instance.name = node_name + "/" + mesh_name;
        instance.node = node;
        instance.mesh = index;
        if (mesh.mNumVertices > 0 && mesh.mVertices == nullptr) fail(mesh_label(index) + ": no vertex positions");
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) instance.base.push_back(to_vec(mesh.mVertices[v]));
        read_faces(mesh, index, instance);
        if (instance.triangles.empty()) return instance;
        read_morph_targets(mesh, index, instance);
        read_bones(mesh, index, instance);
        weld_instance(instance);
        return instance;
    }

    void read_faces(const aiMesh& mesh, unsigned index, MeshInstance& instance) {
        std::vector<std::uint32_t> corners;
        if (mesh.mNumFaces > 0 && mesh.mFaces == nullptr) fail(mesh_label(index) + ": faces missing");
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices < 3) continue;
            if (face.mIndices == nullptr) fail(mesh_label(index) + " face " + std::to_string(f) + ": indices missing");
            corners.assign(face.mIndices, face.mIndices + face.mNumIndices);
            for (const std::uint32_t corner : corners) {
                if (corner < mesh.mNumVertices) continue;
                fail(mesh_label(index) + " face " + std::to_string(f) + ": vertex index " + std::to_string(corner) +
                     " out of range (" + std::to_string(mesh.mNumVertices) + " vertices)");
            }
            append_fan(corners, instance.triangles);
        }
    }

    void read_morph_targets(const aiMesh& mesh, unsigned index, MeshInstance& instance) {
        if (mesh.mNumAnimMeshes > 0 && mesh.mAnimMeshes == nullptr) fail(mesh_label(index) + ": morph targets missing");
        for (unsigned t = 0; t < mesh.mNumAnimMeshes; ++t) {
            const aiAnimMesh* target = mesh.mAnimMeshes[t];
            if (target == nullptr || target->mVertices == nullptr || target->mNumVertices != mesh.mNumVertices) {
                fail(mesh_label(index) + " morph target " + std::to_string(t) +
                     ": positions missing or not one per vertex");
            }
            std::vector<Vec3>& positions = instance.morph_targets.emplace_back();
            for (unsigned v = 0; v < target->mNumVertices; ++v) positions.push_back(to_vec(target->mVertices[v]));
        }
    }

    // Influences per vertex, sorted by bone, zero weights dropped, normalised to sum 1.
    void read_bones(const aiMesh& mesh, unsigned index, MeshInstance& instance) {
        if (mesh.mNumBones == 0) return;
        if (mesh.mBones == nullptr) fail(mesh_label(index) + ": bones missing");
        std::vector<std::vector<std::pair<std::uint32_t, double>>> per_vertex(mesh.mNumVertices);
        double total = 0;
        for (unsigned b = 0; b < mesh.mNumBones; ++b) {
            const aiBone* bone = mesh.mBones[b];
            const std::string label = mesh_label(index) + " bone " + std::to_string(b);
            if (bone == nullptr || (bone->mNumWeights > 0 && bone->mWeights == nullptr)) fail(label + ": missing");
            const auto node = m_node_index.find(bone->mName.C_Str());
            if (node == m_node_index.end()) fail(label + " " + quoted(bone->mName) + " names no node");
            instance.bone_nodes.push_back(node->second);
            instance.bone_offsets.push_back(to_affine(bone->mOffsetMatrix));
            if (!instance.bone_offsets.back().allFinite()) fail(label + ": offset matrix is not finite");
            for (unsigned w = 0; w < bone->mNumWeights; ++w) {
                const aiVertexWeight& weight = bone->mWeights[w];
                if (weight.mVertexId >= mesh.mNumVertices || !std::isfinite(weight.mWeight) || weight.mWeight < 0) {
                    fail(label + " weight " + std::to_string(w) + ": vertex " + std::to_string(weight.mVertexId) +
                         ", weight " + std::to_string(weight.mWeight) + " (expected a vertex < " +
                         std::to_string(mesh.mNumVertices) + " and a finite weight >= 0)");
                }
                if (weight.mWeight == 0) continue;
                per_vertex[weight.mVertexId].emplace_back(b, weight.mWeight);
                total += weight.mWeight;
            }
        }
        if (total == 0) fail(mesh_label(index) + ": every bone weight is zero");
        instance.influence_begin.push_back(0);
        for (auto& influences : per_vertex) {
            std::sort(influences.begin(), influences.end());
            double sum = 0;
            for (const auto& influence : influences) sum += influence.second;
            for (const auto& [bone, weight] : influences) {
                instance.influence_bone.push_back(bone);
                instance.influence_weight.push_back(weight / sum);
            }
            instance.influence_begin.push_back(static_cast<std::uint32_t>(instance.influence_bone.size()));
        }
    }

    void read_clip(unsigned a) {
        if (m_scene.mAnimations == nullptr) fail("clips missing");
        const aiAnimation* animation = m_scene.mAnimations[a];
        const std::string label = "clip " + std::to_string(a);
        if (animation == nullptr) fail(label + ": missing");
        Clip clip;
        clip.name = animation->mName.C_Str();
        clip.duration_ticks = animation->mDuration;
        if (animation->mTicksPerSecond > 0) clip.ticks_per_second = animation->mTicksPerSecond;
        if (!std::isfinite(clip.duration_ticks) || clip.duration_ticks < 0 || !std::isfinite(clip.ticks_per_second)) {
            fail(label + " " + quoted(animation->mName) + ": duration " + std::to_string(animation->mDuration) +
                 " ticks at " + std::to_string(animation->mTicksPerSecond) + " ticks per second");
        }
        const std::string clip_label = label + " " + quoted(animation->mName);
        if ((animation->mNumChannels > 0 && animation->mChannels == nullptr) ||
            (animation->mNumMorphMeshChannels > 0 && animation->mMorphMeshChannels == nullptr)) {
            fail(clip_label + ": channels missing");
        }
        for (unsigned c = 0; c < animation->mNumChannels; ++c) read_channel(*animation, c, clip_label, clip);
        for (unsigned c = 0; c < animation->mNumMorphMeshChannels; ++c) read_morph(*animation, c, clip_label, clip);
        m_model.clips.push_back(std::move(clip));
    }

    template <typename Key>
    void check_order(const std::vector<Key>& keys, const std::string& label) const {
        for (std::size_t k = 1; k < keys.size(); ++k) {
            if (keys[k].time < keys[k - 1].time) fail(label + ": key " + std::to_string(k) + " goes back in time");
        }
    }

    void check_time(double time, const std::string& label) const {
        if (!std::isfinite(time)) fail(label + ": time is not finite");
    }

    // A channel of a node that does not exist moves nothing and is skipped (assimp does the same).
    void read_channel(const aiAnimation& animation, unsigned c, const std::string& clip_label, Clip& clip) {
        const aiNodeAnim* channel = animation.mChannels[c];
        if (channel == nullptr) fail(clip_label + " channel " + std::to_string(c) + ": missing");
        const auto node = m_node_index.find(channel->mNodeName.C_Str());
        if (node == m_node_index.end()) return;
        const std::string label = clip_label + " channel " + std::to_string(c) + " " + quoted(channel->mNodeName);
        if ((channel->mNumPositionKeys > 0 && channel->mPositionKeys == nullptr) ||
            (channel->mNumRotationKeys > 0 && channel->mRotationKeys == nullptr) ||
            (channel->mNumScalingKeys > 0 && channel->mScalingKeys == nullptr)) {
            fail(label + ": keys missing");
        }
        aiVector3D rest_scaling, rest_position;
        aiQuaternion rest_rotation;
        m_ai_nodes[node->second]->mTransformation.Decompose(rest_scaling, rest_rotation, rest_position);
        NodeChannel out;
        out.node = node->second;
        out.position = vector_keys(channel->mPositionKeys, channel->mNumPositionKeys, rest_position, label + " position key ");
        out.scaling = vector_keys(channel->mScalingKeys, channel->mNumScalingKeys, rest_scaling, label + " scaling key ");
        for (unsigned k = 0; k < channel->mNumRotationKeys; ++k) {
            const aiQuatKey& key = channel->mRotationKeys[k];
            const Eigen::Quaterniond q(key.mValue.w, key.mValue.x, key.mValue.y, key.mValue.z);
            const std::string key_label = label + " rotation key " + std::to_string(k);
            check_time(key.mTime, key_label);
            if (!q.coeffs().allFinite() || q.norm() == 0) fail(key_label + ": not a finite non-zero quaternion");
            out.rotation.push_back({key.mTime, q.normalized()});
        }
        if (out.rotation.empty()) {
            const aiQuaternion& r = rest_rotation;
            out.rotation.push_back({0, Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized()});
        }
        check_order(out.position, label + " position keys");
        check_order(out.rotation, label + " rotation keys");
        check_order(out.scaling, label + " scaling keys");
        clip.channels.push_back(std::move(out));
    }

    std::vector<VectorKey> vector_keys(const aiVectorKey* keys, unsigned count, const aiVector3D& rest,
                                       const std::string& label) const {
        std::vector<VectorKey> out;
        for (unsigned k = 0; k < count; ++k) {
            check_time(keys[k].mTime, label + std::to_string(k));
            const Vec3 value = to_vec(keys[k].mValue);
            if (!finite(value)) fail(label + std::to_string(k) + ": value is not finite");
            out.push_back({keys[k].mTime, value});
        }
        if (out.empty()) out.push_back({0, to_vec(rest)});
        return out;
    }

    void read_morph(const aiAnimation& animation, unsigned c, const std::string& clip_label, Clip& clip) {
        const aiMeshMorphAnim* channel = animation.mMorphMeshChannels[c];
        const std::string label = clip_label + " morph channel " + std::to_string(c);
        if (channel == nullptr) fail(label + ": missing");
        const auto node = m_node_index.find(channel->mName.C_Str());
        if (node == m_node_index.end()) fail(label + " " + quoted(channel->mName) + " names no node");
        if (channel->mNumKeys > 0 && channel->mKeys == nullptr) fail(label + ": keys missing");
        MorphChannel out;
        out.node = node->second;
        for (unsigned k = 0; k < channel->mNumKeys; ++k) {
            const aiMeshMorphKey& key = channel->mKeys[k];
            const std::string key_label = label + " key " + std::to_string(k);
            check_time(key.mTime, key_label);
            if (key.mNumValuesAndWeights > 0 && (key.mValues == nullptr || key.mWeights == nullptr)) {
                fail(key_label + ": values missing");
            }
            MorphKey morph{key.mTime, {}};
            for (unsigned i = 0; i < key.mNumValuesAndWeights; ++i) {
                const unsigned target = key.mValues[i];
                if (target > 1u << 16 || !std::isfinite(key.mWeights[i])) {
                    fail(key_label + " value " + std::to_string(i) + ": target " + std::to_string(target) +
                         ", weight " + std::to_string(key.mWeights[i]));
                }
                if (morph.weights.size() <= target) morph.weights.resize(target + 1, 0.0);
                morph.weights[target] = key.mWeights[i];
            }
            out.keys.push_back(std::move(morph));
        }
        check_order(out.keys, label + " keys");
        if (!out.keys.empty()) clip.morphs.push_back(std::move(out));
    }

    // Every morph weight must name a target that each morphed mesh of its node has.
    void check_morph_targets() const {
        for (const Clip& clip : m_model.clips) {
            for (const MorphChannel& morph : clip.morphs) {
                std::size_t targets = 0;
                for (const MorphKey& key : morph.keys) targets = std::max(targets, key.weights.size());
                for (const MeshInstance& instance : m_model.instances) {
                    // A mesh without targets is not morphed; one with fewer than weighed is broken.
                    if (instance.node != morph.node || instance.morph_targets.empty() ||
                        instance.morph_targets.size() >= targets) {
                        continue;
                    }
                    fail("clip '" + clip.name + "' morph channel of node '" + m_model.nodes[morph.node].name +
                         "' weighs target " + std::to_string(targets - 1) + " but " + mesh_label(instance.mesh) +
                         " has " + std::to_string(instance.morph_targets.size()) + " morph targets");
                }
            }
        }
    }

    const aiScene& m_scene;
    const std::filesystem::path& m_file;
    AnimatedModel m_model;
    std::vector<const aiNode*> m_ai_nodes;
    std::unordered_map<std::string, std::uint32_t> m_node_index;
};

}  // namespace

AnimatedModel read_animated_model(const std::filesystem::path& file, bool only_if_animated) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throw InputError(file.string() + ": no such file");
    Assimp::Importer importer;
    return ModelReader(import_checked(importer, file), file).read(only_if_animated);
}

}  // namespace collidescope::animation
