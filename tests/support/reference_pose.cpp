// The reference evaluation (reference_pose.hpp). Deliberately simple and slow.

#include "support/reference_pose.hpp"

#include <cmath>
#include <cstring>

namespace collidescope::reference {
namespace {

using M4 = std::array<std::array<double, 4>, 4>;

M4 identity() {
    M4 m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

M4 from_ai(const aiMatrix4x4& a) {
    M4 m;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) m[r][c] = a[r][c];
    }
    return m;
}

M4 multiply(const M4& a, const M4& b) {
    M4 m{};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            for (int k = 0; k < 4; ++k) m[r][c] += a[r][k] * b[k][c];
        }
    }
    return m;
}

Vec3 transform(const M4& m, const Vec3& p) {
    Vec3 out;
    for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

// Linear search for the last key at or before t; held outside the keys.
template <typename Key>
void find_keys(const Key* keys, unsigned count, double t, unsigned& a, unsigned& b, double& f) {
    if (t <= keys[0].mTime || count == 1) {
        a = b = 0;
        f = 0;
        return;
    }
    if (t >= keys[count - 1].mTime) {
        a = b = count - 1;
        f = 0;
        return;
    }
    unsigned i = 0;
    while (keys[i + 1].mTime <= t) ++i;
    a = i;
    b = i + 1;
    f = (t - keys[a].mTime) / (keys[b].mTime - keys[a].mTime);
}

Vec3 lerp_key(const aiVectorKey* keys, unsigned count, double t) {
    unsigned a, b;
    double f;
    find_keys(keys, count, t, a, b, f);
    const Vec3 va(keys[a].mValue.x, keys[a].mValue.y, keys[a].mValue.z);
    const Vec3 vb(keys[b].mValue.x, keys[b].mValue.y, keys[b].mValue.z);
    return va + f * (vb - va);
}

// Quaternion as (w, x, y, z), unit length.
std::array<double, 4> slerp_key(const aiQuatKey* keys, unsigned count, double t) {
    unsigned a, b;
    double f;
    find_keys(keys, count, t, a, b, f);
    const auto unit = [](const aiQuaternion& q) {
        const double n = std::sqrt(double{q.w} * q.w + double{q.x} * q.x + double{q.y} * q.y + double{q.z} * q.z);
        return std::array<double, 4>{q.w / n, q.x / n, q.y / n, q.z / n};
    };
    const std::array<double, 4> p = unit(keys[a].mValue);
    std::array<double, 4> q = unit(keys[b].mValue);
    double dot = p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3];
    if (dot < 0) {  // the shorter arc
        for (double& c : q) c = -c;
        dot = -dot;
    }
    double sp = 1 - f, sq = f;
    if (dot < 1 - 1e-12) {
        const double theta = std::acos(std::min(dot, 1.0));
        sp = std::sin((1 - f) * theta) / std::sin(theta);
        sq = std::sin(f * theta) / std::sin(theta);
    }
    std::array<double, 4> r;
    double n = 0;
    for (int i = 0; i < 4; ++i) {
        r[i] = sp * p[i] + sq * q[i];
        n += r[i] * r[i];
    }
    for (double& c : r) c /= std::sqrt(n);
    return r;
}

M4 trs(const Vec3& t, const std::array<double, 4>& q, const Vec3& s) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double rot[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                              {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                              {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    M4 m = identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r][c] = rot[r][c] * s[c];
        m[r][3] = t[r];
    }
    return m;
}

const aiNodeAnim* channel_of(const aiAnimation& anim, const aiNode& node) {
    for (unsigned c = 0; c < anim.mNumChannels; ++c) {
        if (std::strcmp(anim.mChannels[c]->mNodeName.C_Str(), node.mName.C_Str()) == 0) return anim.mChannels[c];
    }
    return nullptr;
}

M4 local(const aiAnimation& anim, const aiNode& node, double t) {
    const aiNodeAnim* ch = channel_of(anim, node);
    if (ch == nullptr) return from_ai(node.mTransformation);
    aiVector3D rs, rp;
    aiQuaternion rr;
    node.mTransformation.Decompose(rs, rr, rp);
    const Vec3 position = ch->mNumPositionKeys ? lerp_key(ch->mPositionKeys, ch->mNumPositionKeys, t) : Vec3(rp.x, rp.y, rp.z);
    const Vec3 scaling = ch->mNumScalingKeys ? lerp_key(ch->mScalingKeys, ch->mNumScalingKeys, t) : Vec3(rs.x, rs.y, rs.z);
    aiQuatKey rest{0.0, rr};
    const std::array<double, 4> rotation = ch->mNumRotationKeys ? slerp_key(ch->mRotationKeys, ch->mNumRotationKeys, t)
                                                                : slerp_key(&rest, 1, t);
    return trs(position, rotation, scaling);
}

M4 global(const aiAnimation& anim, const aiNode& node, double t) {
    const M4 own = local(anim, node, t);
    return node.mParent == nullptr ? own : multiply(global(anim, *node.mParent, t), own);
}

const aiNode* find_node(const aiNode& root, const char* name) {
    if (std::strcmp(root.mName.C_Str(), name) == 0) return &root;
    for (unsigned c = 0; c < root.mNumChildren; ++c) {
        if (const aiNode* found = find_node(*root.mChildren[c], name)) return found;
    }
    return nullptr;
}

// Morph weight of target `target` at t: linear between keys, held outside.
double morph_weight(const aiAnimation& anim, const aiNode& node, unsigned target, double t) {
    for (unsigned c = 0; c < anim.mNumMorphMeshChannels; ++c) {
        const aiMeshMorphAnim& ch = *anim.mMorphMeshChannels[c];
        if (std::strcmp(ch.mName.C_Str(), node.mName.C_Str()) != 0 || ch.mNumKeys == 0) continue;
        const auto weight_at = [&](const aiMeshMorphKey& key) {
            for (unsigned i = 0; i < key.mNumValuesAndWeights; ++i) {
                if (key.mValues[i] == target) return key.mWeights[i];
            }
            return 0.0;
        };
        unsigned a, b;
        double f;
        find_keys(ch.mKeys, ch.mNumKeys, t, a, b, f);
        return (1 - f) * weight_at(ch.mKeys[a]) + f * weight_at(ch.mKeys[b]);
    }
    return 0;
}

Vec3 pose_vertex(const aiScene& scene, const aiAnimation& anim, const aiNode& node, const aiMesh& mesh,
                 unsigned v, double t) {
    const Vec3 base(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z);
    Vec3 p = base;
    for (unsigned m = 0; m < mesh.mNumAnimMeshes; ++m) {
        const aiVector3D& target = mesh.mAnimMeshes[m]->mVertices[v];
        p += morph_weight(anim, node, m, t) * (Vec3(target.x, target.y, target.z) - base);
    }
    if (mesh.mNumBones == 0) return transform(global(anim, node, t), p);
    double total = 0;
    Vec3 sum = Vec3::Zero();
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const aiBone& bone = *mesh.mBones[b];
        for (unsigned w = 0; w < bone.mNumWeights; ++w) {
            if (bone.mWeights[w].mVertexId != v) continue;
            const aiNode* joint = find_node(*scene.mRootNode, bone.mName.C_Str());
            const M4 matrix = multiply(global(anim, *joint, t), from_ai(bone.mOffsetMatrix));
            sum += bone.mWeights[w].mWeight * transform(matrix, p);
            total += bone.mWeights[w].mWeight;
        }
    }
    if (total == 0) return transform(global(anim, node, t), p);  // no influence: follows its node
    return sum / total;
}

void visit(const aiScene& scene, const aiAnimation& anim, const aiNode& node, double t,
           std::vector<PosedInstance>& out) {
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        PosedInstance instance;
        instance.name = std::string(node.mName.C_Str()) + "/" + mesh.mName.C_Str();
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            for (unsigned c = 1; c + 1 < face.mNumIndices; ++c) {
                instance.triangles.push_back({face.mIndices[0], face.mIndices[c], face.mIndices[c + 1]});
            }
        }
        if (instance.triangles.empty()) continue;
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) instance.vertices.push_back(pose_vertex(scene, anim, node, mesh, v, t));
        out.push_back(std::move(instance));
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) visit(scene, anim, *node.mChildren[c], t, out);
}

}  // namespace

std::vector<PosedInstance> pose(const aiScene& scene, unsigned clip, double ticks) {
    std::vector<PosedInstance> out;
    visit(scene, *scene.mAnimations[clip], *scene.mRootNode, ticks, out);
    return out;
}

}  // namespace collidescope::reference
