#pragma once
// The FCL 0.7 peer (bench/peers): one BVHModel<AABB> per object, refit bottom-up every frame,
// exhaustive contacts between objects through FCL's own floating-point triangle test, with no
// contact points (enable_contact off: FCL then records each intersecting triangle pair and
// computes nothing more, as the engine reports pairs only). Object pairs run in parallel on
// TBB's threads (FCL's traversal of one pair is sequential). FCL has no self-collision, so
// (a, a) object pairs are skipped: its figures are between objects only.

#include "peers/peer_common.hpp"

#include "collidescope/frame_context.hpp"

#include <fcl/fcl.h>
#include <tbb/parallel_for.h>

#include <limits>
#include <memory>
#include <span>

namespace collidescope::peers {

class FclPeer {
public:
    /// The pairs FCL reports between the objects of every object pair (a != b).
    PairSet frame(const Frame& frame, std::span<const ObjectPair> object_pairs) {
        if (m_models.empty() || revisions(frame) != m_revisions) {
            m_models.clear();
            m_objects.clear();
            create(frame);
            m_revisions = revisions(frame);
        }
        for (std::size_t o = 0; o < m_models.size(); ++o) {
            m_models[o]->beginUpdateModel();
            m_models[o]->updateSubModel(points(frame.objects[o]));
            m_models[o]->endUpdateModel(true, true);  // refit, bottom-up
            m_objects[o]->computeAABB();
        }
        std::vector<ObjectPair> between;
        for (const ObjectPair& pair : object_pairs) {
            if (pair.a != pair.b) between.push_back(pair);
        }
        std::vector<PairSet> found(between.size());
        tbb::parallel_for(std::size_t{0}, between.size(), [&](std::size_t k) {
            const ObjectPair& pair = between[k];
            // Exhaustive, without contact points (the second argument: enable_contact).
            fcl::CollisionRequestd request(std::numeric_limits<std::size_t>::max(), false);
            fcl::CollisionResultd result;
            fcl::collide(m_objects[pair.a].get(), m_objects[pair.b].get(), request, result);
            for (std::size_t i = 0; i < result.numContacts(); ++i) {
                const fcl::Contactd& contact = result.getContact(i);
                found[k].push_back({pair.a, static_cast<std::uint32_t>(contact.b1), pair.b, static_cast<std::uint32_t>(contact.b2)});
            }
        });
        PairSet pairs;
        for (const PairSet& some : found) pairs.insert(pairs.end(), some.begin(), some.end());
        return pairs;
    }

private:
    using Model = fcl::BVHModel<fcl::AABBd>;

    static std::vector<fcl::Vector3d> points(const ObjectFrame& mesh) {
        std::vector<fcl::Vector3d> out(mesh.vertices.begin(), mesh.vertices.end());
        return out;
    }

    void create(const Frame& frame) {
        for (const ObjectFrame& mesh : frame.objects) {
            auto model = std::make_shared<Model>();
            std::vector<fcl::Triangle> triangles;
            for (const TriIndices& t : mesh.topology->triangles) triangles.emplace_back(t[0], t[1], t[2]);
            model->beginModel();
            model->addSubModel(points(mesh), triangles);
            model->endModel();
            m_models.push_back(model);
            m_objects.push_back(std::make_unique<fcl::CollisionObjectd>(model));
        }
    }

    std::vector<std::shared_ptr<Model>> m_models;
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> m_objects;
    std::vector<std::uint64_t> m_revisions;
};

}  // namespace collidescope::peers
