// The query cache: a table that finds only what was stored in this interval, never another key's,
// and test_pair through it: the same outcome as without, in any order of the pairs (each query
// a pure function of its key), on random scenes' every triangle pair, seeds printed.

#include "ccd/pair_motion.hpp"
#include "ccd/query_cache.hpp"
#include "support/scene_builders.hpp"
#include "support/sweep_size.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

namespace collidescope::ccd {
namespace {

TEST(QueryCache, FindsOnlyWhatThisIntervalStoredAndKeepsMostOfAFewThousand) {
    QueryCache cache;
    const auto result_of = [](std::size_t n) {
        QueryResult r;
        r.hit = n % 3 == 0;
        r.toi = 1.0 / static_cast<double>(n + 1);
        r.boxes = static_cast<std::uint32_t>(n);
        return r;
    };
    // Keys that differ in one word each: forms, objects, vertices, the planar axis.
    std::vector<QueryKey> keys;
    for (std::uint32_t n = 0; n < 1000; ++n) {
        keys.push_back(QueryKey::vertex_face(n % 3, n, 1, n / 2, static_cast<int>(n % 4) - 1));
        keys.push_back(QueryKey::edge_edge(n % 3, n, n + 1, 1, n / 2, n / 2 + 1));
    }
    for (std::size_t k = 0; k < keys.size(); k += 2) cache.insert(keys[k], {result_of(k), k % 4 == 0});
    std::size_t found_count = 0;
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const CachedQuery* found = cache.find(keys[k]);
        if (k % 2 == 1) {
            EXPECT_EQ(found, nullptr) << "key " << k << " was never stored";
            continue;
        }
        if (found == nullptr) continue;  // its slot taken by a later key
        ++found_count;
        EXPECT_EQ(found->result.boxes, k);  // never another key's result
        EXPECT_EQ(found->result.hit, result_of(k).hit);
        EXPECT_EQ(found->cleared, k % 4 == 0);
    }
    EXPECT_EQ(cache.size(), found_count);
    EXPECT_GT(found_count, 800u);  // 1,000 keys in 4,096 slots: most keep theirs
    // A key stored twice keeps the first (the same result: pure functions of the key).
    const auto kept = std::find_if(keys.begin(), keys.end(), [&](const QueryKey& key) { return cache.find(key) != nullptr; });
    ASSERT_NE(kept, keys.end());
    const std::uint32_t boxes = cache.find(*kept)->result.boxes;
    cache.insert(*kept, {result_of(7), false});
    EXPECT_EQ(cache.find(*kept)->result.boxes, boxes);
    // The planar axis is part of the key.
    EXPECT_EQ(cache.find(QueryKey::vertex_face(0, 0, 1, 0, 0)), nullptr);
    cache.next_interval();
    EXPECT_EQ(cache.size(), 0u);
    for (const QueryKey& key : keys) EXPECT_EQ(cache.find(key), nullptr);
    cache.insert(keys[1], {result_of(1), false});
    EXPECT_NE(cache.find(keys[1]), nullptr);
}

bool shares_vertices(const Topology& topology) {
    std::vector<int> uses(topology.vertex_count, 0);
    for (const TriIndices& t : topology.triangles) {
        for (const std::uint32_t v : t) {
            if (++uses[v] > 1) return true;
        }
    }
    return false;
}

TEST(QueryCache, PairsGetTheSameOutcomeThroughACacheInAnyOrder) {
    std::uint64_t pairs = 0, contacts = 0, asked = 0, stored = 0;
    for (const std::uint64_t seed : testing::sweep_of<std::uint64_t>({31, 32, 33, 34, 35, 36}, 3)) {
        std::printf("[ seed     ] QueryCache random scene: seed %llu\n", static_cast<unsigned long long>(seed));
        testing::RandomSceneConfig config;
        config.objects = 3;
        config.frames = 2;
        config.max_triangles = 24;
        config.sheet_cells = 4;
        const std::vector<Frame> frames = testing::all_frames(testing::random_scene(seed, config));
        const Frame& from = frames[0];
        const Frame& to = frames[1];
        // Every triangle pair, of two objects and of one (self), as the walk would make it.
        std::vector<PairMotion> motions;
        for (std::uint32_t x = 0; x < from.objects.size(); ++x) {
            for (std::uint32_t y = x; y < from.objects.size(); ++y) {
                const Topology& tx = *from.objects[x].topology;
                const Topology& ty = *from.objects[y].topology;
                for (std::uint32_t a = 0; a < tx.triangles.size(); ++a) {
                    for (std::uint32_t b = x == y ? a + 1 : 0; b < ty.triangles.size(); ++b) {
                        PairMotion m;
                        m.ia = tx.triangles[a];
                        m.ib = ty.triangles[b];
                        for (int i = 0; i < 3; ++i) {
                            m.a[i] = {from.objects[x].vertices[m.ia[i]], to.objects[x].vertices[m.ia[i]]};
                            m.b[i] = {from.objects[y].vertices[m.ib[i]], to.objects[y].vertices[m.ib[i]]};
                        }
                        m.self = x == y;
                        m.object_a = x;
                        m.tri_a = a;
                        m.object_b = y;
                        m.tri_b = b;
                        m.shares_a = shares_vertices(tx);
                        m.shares_b = shares_vertices(ty);
                        motions.push_back(m);
                    }
                }
            }
        }
        std::vector<PairOutcome> plain;
        for (const PairMotion& m : motions) plain.push_back(test_pair(m, 1e-3, 50000));
        // Forward, then in a shuffled order, each through its own cache.
        std::vector<std::size_t> order(motions.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
        for (const bool shuffle : {false, true}) {
            if (shuffle) std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
            QueryCache cache;
            std::uint64_t queries = 0;
            for (const std::size_t k : order) {
                const PairOutcome cached = test_pair(motions[k], 1e-3, 50000, &cache);
                const PairOutcome& expected = plain[k];
                const std::string what = "seed " + std::to_string(seed) + " pair " + std::to_string(k) + (shuffle ? " shuffled" : "");
                EXPECT_EQ(cached.contact, expected.contact) << what;
                EXPECT_EQ(cached.start_contact, expected.start_contact) << what;
                EXPECT_EQ(cached.end_contact, expected.end_contact) << what;
                if (cached.contact && expected.contact) {
                    EXPECT_EQ(cached.toi, expected.toi) << what;
                }
                EXPECT_EQ(cached.resolved, expected.resolved) << what;
                EXPECT_EQ(cached.queries, expected.queries) << what;  // asked, found or solved
                EXPECT_EQ(cached.boxes, expected.boxes) << what;      // a found one's counted as solved
                queries += cached.queries;
            }
            asked += queries;
            stored += cache.size();
        }
        pairs += motions.size();
        for (const PairOutcome& o : plain) contacts += o.contact;
    }
    std::printf("%llu pairs, %llu contacts; %llu queries asked through the caches, %llu stored\n",
                static_cast<unsigned long long>(pairs), static_cast<unsigned long long>(contacts),
                static_cast<unsigned long long>(asked), static_cast<unsigned long long>(stored));
    EXPECT_GT(contacts, 100u);
    EXPECT_LT(stored, asked);  // queries recurred, and were found
}

}  // namespace
}  // namespace collidescope::ccd
