// write_tiny_rig: an aiScene built by hand, exported as assbin.

#include "support/tiny_rig.hpp"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace collidescope::testing {
namespace {

aiNode* make_node(const char* name, aiNode* parent) {
    auto* node = new aiNode(name);
    node->mParent = parent;
    return node;
}

aiMesh* make_quad(const TinyRigOptions& options) {
    auto* mesh = new aiMesh();
    mesh->mName = "quad";
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = 5;
    mesh->mVertices = new aiVector3D[5]{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh->mNumFaces = 2;
    mesh->mFaces = new aiFace[2];
    const unsigned corners[2][3] = {{0, 1, 2}, {0, 4, 3}};
    for (int f = 0; f < 2; ++f) {
        mesh->mFaces[f].mNumIndices = 3;
        mesh->mFaces[f].mIndices = new unsigned[3]{corners[f][0], corners[f][1], corners[f][2]};
    }
    mesh->mNumBones = 1;
    mesh->mBones = new aiBone*[1];
    auto* bone = new aiBone();
    bone->mName = options.unknown_bone ? "elbow" : "arm";
    bone->mNumWeights = 5;
    bone->mWeights = new aiVertexWeight[5];
    for (unsigned v = 0; v < 5; ++v) bone->mWeights[v] = aiVertexWeight(v, options.zero_weights ? 0.0f : 1.0f);
    mesh->mBones[0] = bone;
    return mesh;
}

aiNodeAnim* make_rise_channel(const TinyRigOptions& options) {
    auto* channel = new aiNodeAnim();
    channel->mNodeName = "arm";
    channel->mNumPositionKeys = 2;
    channel->mPositionKeys = new aiVectorKey[2];
    channel->mPositionKeys[0] = aiVectorKey(0, aiVector3D(0, 0, 0));
    const float z = options.nan_key ? std::numeric_limits<float>::quiet_NaN() : 2.0f;
    channel->mPositionKeys[1] = aiVectorKey(10, aiVector3D(0, 0, z));
    channel->mNumRotationKeys = 1;
    channel->mRotationKeys = new aiQuatKey[1];
    channel->mRotationKeys[0] = aiQuatKey(0, aiQuaternion());
    channel->mNumScalingKeys = 1;
    channel->mScalingKeys = new aiVectorKey[1];
    channel->mScalingKeys[0] = aiVectorKey(0, aiVector3D(1, 1, 1));
    return channel;
}

aiAnimation* make_clip(const char* name, aiNodeAnim* channel, double duration) {
    auto* clip = new aiAnimation();
    clip->mName = name;
    clip->mDuration = duration;
    clip->mTicksPerSecond = 10;
    clip->mNumChannels = 1;
    clip->mChannels = new aiNodeAnim*[1]{channel};
    return clip;
}

}  // namespace

void write_tiny_rig(const std::filesystem::path& file, const TinyRigOptions& options) {
    auto scene = std::make_unique<aiScene>();
    aiNode* root = make_node("root", nullptr);
    aiNode* body = make_node("body", root);
    aiNode* arm = make_node("arm", root);
    root->addChildren(2, std::array<aiNode*, 2>{body, arm}.data());
    body->mNumMeshes = 1;
    body->mMeshes = new unsigned[1]{0};
    scene->mRootNode = root;
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh*[1]{make_quad(options)};
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
    scene->mNumAnimations = options.second_clip ? 2 : 1;
    scene->mAnimations = new aiAnimation*[scene->mNumAnimations];
    scene->mAnimations[0] = make_clip("rise", make_rise_channel(options), 10);
    if (options.second_clip) {
        TinyRigOptions still;
        aiNodeAnim* rest = make_rise_channel(still);
        rest->mNumPositionKeys = 1;  // the first key only: the bone stays at rest
        scene->mAnimations[1] = make_clip("idle", rest, 5);
    }
    Assimp::Exporter exporter;
    if (exporter.Export(scene.get(), "assbin", file.string()) != aiReturn_SUCCESS) {
        throw std::runtime_error("cannot export the tiny rig to " + file.string() + ": " + exporter.GetErrorString());
    }
}

}  // namespace collidescope::testing
