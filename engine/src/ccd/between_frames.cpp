// Between-frames detection: each object's AABB tree (bvh/) fitted to its triangles' swept
// boxes (the box of a triangle's corners at both ends, which holds the triangle at every time
// between, as the motion is linear), kept from interval to interval: refit, and built over
// those boxes again once its refits have degraded it (fit_swept); the trees of
// every object pair whose swept boxes meet are walked together (and each object's own, with
// self-collision, skipping nodes whose triangles are proven embedded throughout the interval:
// swept_patches.hpp), and each pair of triangles whose swept boxes overlap is tested
// (pair_motion.hpp) where the walk finds it, in parallel over the walk's top items. Between
// objects the walk runs on the trees' 4-wide float layouts (bvh/wide_step.hpp), as the
// per-frame traversal does; it reaches exactly the binary walk's pairs.

#include "collidescope/between_frames.hpp"

#include "bvh/bvh.hpp"
#include "bvh/surface_patches.hpp"
#include "bvh/wide_step.hpp"
#include "ccd/interval_checks.hpp"
#include "ccd/pair_motion.hpp"
#include "ccd/swept_patches.hpp"
#include "stages/pair_order.hpp"
#include "stats/stopwatch.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace collidescope {
namespace {

using bvh::Tree;

// One object's swept tree, kept while its topology stays.
struct SweptTree {
    std::uint64_t revision = 0;
    Tree tree;
    double built_quality = 0;  ///< the swept refit's best quality since the last build
    bool rebuild_due = false;  ///< the last refit degraded the tree: build it at the next interval
    bool self = false;
    /// With self-collision on a surface (bvh::surface_like): the tree has patches, and per
    /// node the projected orientations kept throughout the interval (swept_node_sides).
    bool patched = false;
    std::vector<std::uint8_t> sides;
    /// Some vertex lies in two triangles (not a soup): its queries recur across pairs.
    bool shares_vertices = false;
};

bool shares_vertices(const Topology& topology) {
    std::vector<bool> used(topology.vertex_count, false);
    for (const TriIndices& t : topology.triangles) {
        for (const std::uint32_t v : t) {
            if (v < used.size() && used[v]) return true;
            if (v < used.size()) used[v] = true;
        }
    }
    return false;
}

// Fits `swept` to the triangles' boxes over the interval (each the box of its corners at both
// ends): built over them for a new topology, then refit; built over them again at the next
// interval once a refit has made it more than k_rebuild_plain (k_rebuild_patched) times as
// costly as at its best since its build (the motion's own growth of the boxes is in both). A
// build reads each corner once, as the refit it replaces does, so it costs little more (the
// sort): on the flying soups a tree kept until twice as costly walked about twice the node
// pairs of a fresh one. A tree with patches (self-collision on a surface) costs more to build
// and its walk skips the embedded patches: on the cloth family a lower threshold cost more
// than it saved. With `self` on a surface, the tree also carries the patches of
// self-collision culling and their sides over the interval. `builder` keeps the builds'
// working memory for the next (first touches of fresh memory were most of a build's time:
// bvh.hpp), one set per build running at once rather than per object.
void fit_swept(SweptTree& swept, const Topology& topology, std::span<const Vec3> from, std::span<const Vec3> to,
               bool self, bvh::TreeBuilder& builder) {
    constexpr double k_rebuild_plain = 1.5, k_rebuild_patched = 2.0;
    Tree& tree = swept.tree;
    bool build = swept.rebuild_due;
    if (swept.revision != topology.revision || topology.revision == 0 || tree.empty() || swept.self != self) {
        swept.self = self;
        swept.patched = self && bvh::surface_like(topology.triangles);  // O(n log n): once per topology
        swept.shares_vertices = shares_vertices(topology);
        swept.revision = topology.revision;
        build = true;
    }
    if (build) {
        bvh::BuildConfig config;
        config.surface_patches = swept.patched;
        builder.build_swept(topology.triangles, from, to, config, tree);
        swept.built_quality = 1.0;
        swept.rebuild_due = false;
    } else if (!tree.empty()) {
        const bvh::RefitStats fitted = bvh::refit_swept(tree, topology.triangles, from, to);
        // The reference: the best since the build (one built in a fast interval, whose swept
        // boxes are large, would otherwise set it too high for the slower ones after it).
        swept.built_quality = std::min(swept.built_quality, fitted.quality);
        swept.rebuild_due = fitted.quality > (swept.patched ? k_rebuild_patched : k_rebuild_plain) * swept.built_quality;
    }
    if (tree.empty()) {
        swept.sides.clear();
        return;
    }
    if (swept.patched && !tree.patches.empty()) {
        ccd::swept_node_sides(tree, from, to, swept.sides);
    } else {
        swept.sides.clear();
    }
}

// A unit of the walk: node a of object x against node b of object y, or (self) below one node;
// with `wide`, a and b are entries of the wide layouts (x != y) whose boxes overlap.
struct Item {
    std::uint32_t x, y, a, b;
    bool self;
    bool wide = false;
};

struct ThreadResult {
    std::vector<IntervalContact> contacts;
    std::uint64_t candidates = 0, start_contacts = 0, queries = 0, boxes = 0;
    ccd::QueryCache* cache = nullptr;  ///< this thread's, kept from interval to interval
};

class Walk {
public:
    Walk(const Frame& from, const Frame& to, std::span<const SweptTree* const> trees, double tolerance,
         std::uint32_t max_boxes)
        : m_from(from), m_to(to), m_trees(trees), m_tolerance(tolerance), m_max_boxes(max_boxes) {}

    // Expands `item` one step: follow-up items onto `stack`, leaf pairs tested.
    void step(const Item& item, std::vector<Item>& stack, ThreadResult& out) const {
        const Tree& tx = m_trees[item.x]->tree;
        const Tree& ty = m_trees[item.y]->tree;
        if (item.wide) {
            bvh::wide::step(
                tx, item.a, ty, item.b,
                [&](std::uint32_t a, std::uint32_t b) {
                    prefetch_entry(tx, a);
                    prefetch_entry(ty, b);
                    stack.push_back({item.x, item.y, a, b, false, true});
                },
                [&](std::uint32_t first_a, std::uint32_t count_a, std::uint32_t first_b, std::uint32_t count_b) {
                    // The slot pairs whose boxes overlap first, then each tested while the
                    // next one's corners are asked for (a gather from four places in memory).
                    static_assert(bvh::k_wide_max_leaf <= 8, "a leaf entry's count has three bits");
                    std::array<std::array<std::uint32_t, 2>, bvh::k_wide_max_leaf * bvh::k_wide_max_leaf> found;  // not zeroed
                    std::size_t count = 0;
                    for (std::uint32_t i = first_a; i < first_a + count_a; ++i) {
                        const bvh::Aabb& box = tx.leaf_boxes[i];
                        for (std::uint32_t j = first_b; j < first_b + count_b; ++j) {
                            if (bvh::overlaps(box, ty.leaf_boxes[j])) found[count++] = {i, j};
                        }
                    }
                    for (std::size_t k = 0; k < count; ++k) {
                        if (k + 1 < count) prefetch_corners(item.x, tx, found[k + 1][0], item.y, ty, found[k + 1][1]);
                        candidate(item.x, tx, found[k][0], item.y, ty, found[k][1], out);
                    }
                });
            return;
        }
        const bvh::Node& na = tx.nodes[item.a];
        if (item.self) {
            // Triangles proven embedded throughout the interval: no pair below to test.
            const SweptTree& swept = *m_trees[item.x];
            if (!swept.sides.empty() &&
                ccd::swept_patch_is_embedded(tx, swept.sides, item.a, m_from.objects[item.x].vertices.span(),
                                             m_to.objects[item.x].vertices.span())) {
                return;
            }
            if (na.is_leaf()) {
                for (std::uint32_t i = 0; i < na.count; ++i)
                    for (std::uint32_t j = i + 1; j < na.count; ++j) leaf_pair(item.x, tx, na.index + i, item.y, ty, na.index + j, out);
                return;
            }
            const std::uint32_t left = item.a + 1, right = na.index;
            stack.push_back({item.x, item.x, left, right, false});
            stack.push_back({item.x, item.x, right, right, true});
            stack.push_back({item.x, item.x, left, left, true});
            return;
        }
        const bvh::Node& nb = ty.nodes[item.b];
        if (!bvh::overlaps(na.box, nb.box)) return;
        if (na.is_leaf() && nb.is_leaf()) {
            for (std::uint32_t i = 0; i < na.count; ++i)
                for (std::uint32_t j = 0; j < nb.count; ++j) leaf_pair(item.x, tx, na.index + i, item.y, ty, nb.index + j, out);
            return;
        }
        // Split the larger (or the inner) node; only the children whose boxes meet the other
        // node's go on the stack (a push and a pop cost more than the test: on D's flying soup,
        // 3% of the interval's instructions).
        const bool split_a = !na.is_leaf() && (nb.is_leaf() || na.box.half_area() >= nb.box.half_area());
        if (split_a) {
            for (const std::uint32_t child : {item.a + 1, na.index}) {
                if (bvh::overlaps(tx.nodes[child].box, nb.box)) stack.push_back({item.x, item.y, child, item.b, false});
            }
        } else {
            for (const std::uint32_t child : {item.b + 1, nb.index}) {
                if (bvh::overlaps(na.box, ty.nodes[child].box)) stack.push_back({item.x, item.y, item.a, child, false});
            }
        }
    }

private:
    // Asks for the cache lines of `bytes` bytes from `data`.
    static void prefetch_lines(const void* data, std::size_t bytes) {
        const auto first = reinterpret_cast<std::uintptr_t>(data) & ~std::uintptr_t{63};
        const auto last = reinterpret_cast<std::uintptr_t>(data) + bytes - 1;
        for (std::uintptr_t line = first; line <= last; line += 64) __builtin_prefetch(reinterpret_cast<const void*>(line));
    }

    // Asks for an entry's data ahead of its step (the walk reaches leaves and nodes in no
    // order the hardware can guess: on the exploded dragon the reads of two leaves' boxes
    // were a quarter of the walk's time): a leaf's triangle boxes and its float box, or a
    // wide node.
    static void prefetch_entry(const Tree& tree, std::uint32_t entry) {
        if (bvh::is_wide_leaf(entry)) {
            const std::uint32_t first = bvh::wide_leaf_first(entry);
            const std::uint32_t count = bvh::wide_leaf_count(entry);
            prefetch_lines(tree.leaf_boxes.data() + first, count * sizeof(bvh::Aabb));
            prefetch_lines(tree.leaf_triangles.data() + first, count * sizeof(TriIndices));
            prefetch_lines(tree.triangle_ids.data() + first, count * sizeof(std::uint32_t));
            __builtin_prefetch(tree.wide.leaf_box_at.data() + first);
        } else {
            prefetch_lines(tree.wide.nodes.data() + entry, sizeof(bvh::WideNode));
        }
    }

    // Asks for the corners of slots sa of x's tree and sb of y's at both ends.
    void prefetch_corners(std::uint32_t x, const Tree& tx, std::uint32_t sa, std::uint32_t y, const Tree& ty,
                          std::uint32_t sb) const {
        for (const auto& [object, tree, slot] : {std::tuple{x, &tx, sa}, std::tuple{y, &ty, sb}}) {
            const Vec3* at_from = m_from.objects[object].vertices.data();
            const Vec3* at_to = m_to.objects[object].vertices.data();
            for (const std::uint32_t v : tree->leaf_triangles[slot]) {
                __builtin_prefetch(at_from + v);
                __builtin_prefetch(at_to + v);
            }
        }
    }

    // Slots sa of x's tree and sb of y's: a candidate when their swept boxes overlap (most
    // slot pairs of two leaves do not: the test stays inline, the candidate's work does not).
    void leaf_pair(std::uint32_t x, const Tree& tx, std::uint32_t sa, std::uint32_t y, const Tree& ty, std::uint32_t sb,
                   ThreadResult& out) const {
        if (bvh::overlaps(tx.leaf_boxes[sa], ty.leaf_boxes[sb])) candidate(x, tx, sa, y, ty, sb, out);
    }

    [[gnu::noinline]] void candidate(std::uint32_t x, const Tree& tx, std::uint32_t sa, std::uint32_t y, const Tree& ty,
                                     std::uint32_t sb, ThreadResult& out) const {
        ++out.candidates;
        const std::uint32_t tri_x = tx.triangle_ids[sa];
        const TrianglePair pair = make_pair_ordered(x, tri_x, y, ty.triangle_ids[sb]);
        ccd::PairMotion motion;
        const ObjectFrame& a0 = m_from.objects[pair.obj_a];
        const ObjectFrame& a1 = m_to.objects[pair.obj_a];
        const ObjectFrame& b0 = m_from.objects[pair.obj_b];
        const ObjectFrame& b1 = m_to.objects[pair.obj_b];
        // The trees' own copies of the triangles, in leaf order (where the walk has just been),
        // not the topology's (a gather from anywhere).
        const bool x_first = pair.obj_a == x && pair.tri_a == tri_x;
        motion.ia = x_first ? tx.leaf_triangles[sa] : ty.leaf_triangles[sb];
        motion.ib = x_first ? ty.leaf_triangles[sb] : tx.leaf_triangles[sa];
        for (int i = 0; i < 3; ++i) {
            motion.a[i] = {a0.vertices[motion.ia[i]], a1.vertices[motion.ia[i]]};
            motion.b[i] = {b0.vertices[motion.ib[i]], b1.vertices[motion.ib[i]]};
        }
        motion.self = pair.obj_a == pair.obj_b;
        motion.object_a = pair.obj_a;
        motion.tri_a = pair.tri_a;
        motion.object_b = pair.obj_b;
        motion.tri_b = pair.tri_b;
        motion.shares_a = m_trees[pair.obj_a]->shares_vertices;
        motion.shares_b = m_trees[pair.obj_b]->shares_vertices;
        const ccd::PairOutcome outcome = ccd::test_pair(motion, m_tolerance, m_max_boxes, out.cache);
        out.queries += outcome.queries;
        out.boxes += outcome.boxes;
        out.start_contacts += outcome.start_contact;
        if (outcome.contact) {
            out.contacts.push_back({pair, outcome.toi, !outcome.start_contact && !outcome.end_contact, outcome.resolved});
        }
    }

    const Frame& m_from;
    const Frame& m_to;
    std::span<const SweptTree* const> m_trees;
    double m_tolerance;
    std::uint32_t m_max_boxes;
};

}  // namespace

struct BetweenFrames::State {
    std::vector<SweptTree> trees;
    bvh::TreeBuilder builder;  ///< the swept trees' builds (thread-safe)
    tbb::enumerable_thread_specific<ccd::QueryCache> caches;  ///< each thread's query results
};

BetweenFrames::BetweenFrames(BetweenFramesOptions options) : m_options(options), m_state(std::make_unique<State>()) {
    m_options.max_boxes = std::max<std::uint32_t>(m_options.max_boxes, 1);
}
BetweenFrames::~BetweenFrames() = default;

IntervalResult BetweenFrames::detect(const Frame& from, const Frame& to) {
    const Stopwatch whole;
    const double tolerance = ccd::check_interval(from, to, m_options.tolerance);
    IntervalResult result;
    IntervalStats& stats = result.stats;
    stats.tolerance = tolerance;
    const std::size_t n = from.objects.size();
    m_state->trees.resize(n);
    Stopwatch broad;
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        fit_swept(m_state->trees[i], *from.objects[i].topology, from.objects[i].vertices.span(),
                  to.objects[i].vertices.span(), m_options.self_collision, m_state->builder);
    });
    // The object pairs whose swept boxes meet, in order, and the wide layouts of their objects
    // (the swept refit does not keep one fitted on the way: a pass of its own, only where the
    // walk will use it; on the way, it made the refit slower than both: bvh/refit.cpp).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> meeting;
    std::vector<std::uint32_t> paired;
    {
        std::vector<bool> is_paired(n, false);
        for (std::uint32_t x = 0; x < n; ++x) {
            const Tree& tx = m_state->trees[x].tree;
            for (std::uint32_t y = x + 1; y < n && !tx.empty(); ++y) {
                const Tree& ty = m_state->trees[y].tree;
                if (ty.empty() || !bvh::overlaps(tx.nodes[0].box, ty.nodes[0].box)) continue;
                meeting.emplace_back(x, y);
                is_paired[x] = is_paired[y] = true;
            }
        }
        for (std::uint32_t x = 0; x < n; ++x) {
            if (is_paired[x]) paired.push_back(x);
        }
    }
    tbb::parallel_for(std::size_t{0}, paired.size(), [&](std::size_t k) { bvh::fit_wide(m_state->trees[paired[k]].tree); });
    stats.broad_ms = broad.elapsed_ms();
    const Stopwatch narrow;
    std::vector<const SweptTree*> trees;
    for (const SweptTree& t : m_state->trees) trees.push_back(&t);
    for (ccd::QueryCache& cache : m_state->caches) cache.next_interval();
    const Walk walk(from, to, trees, stats.tolerance, m_options.max_boxes);
    // The roots: every object pair whose swept boxes meet, and each object's own.
    std::vector<Item> items;
    auto next_meeting = meeting.begin();
    for (std::uint32_t x = 0; x < n; ++x) {
        if (trees[x]->tree.empty()) continue;
        if (m_options.self_collision) items.push_back({x, x, 0, 0, true});
        for (; next_meeting != meeting.end() && next_meeting->first == x; ++next_meeting) {
            const std::uint32_t y = next_meeting->second;
            const Tree& tx = trees[x]->tree;
            const Tree& ty = trees[y]->tree;
            if (bvh::wide_fitted(tx) && bvh::wide_fitted(ty)) {
                items.push_back({x, y, bvh::wide_root(tx), bvh::wide_root(ty), false, true});
            } else {
                items.push_back({x, y, 0, 0, false});
            }
        }
    }
    // Breadth-first until there are enough items for the threads (a fixed number, so the
    // counts do not depend on the thread count), then each item to its end on one thread.
    tbb::enumerable_thread_specific<ThreadResult> per_thread;
    {
        ThreadResult& serial = per_thread.local();
        serial.cache = &m_state->caches.local();
        constexpr std::size_t k_items = 256;
        std::vector<Item> next;
        while (!items.empty() && items.size() < k_items) {
            next.clear();
            for (const Item& item : items) walk.step(item, next, serial);
            items.swap(next);
        }
    }
    tbb::parallel_for(std::size_t{0}, items.size(), [&](std::size_t k) {
        ThreadResult& out = per_thread.local();
        if (out.cache == nullptr) out.cache = &m_state->caches.local();
        thread_local std::vector<Item> stack;
        stack.assign(1, items[k]);
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            walk.step(item, stack, out);
        }
    });
    for (ThreadResult& t : per_thread) {
        result.contacts.insert(result.contacts.end(), t.contacts.begin(), t.contacts.end());
        stats.candidate_pairs += t.candidates;
        stats.start_contacts += t.start_contacts;
        stats.primitive_queries += t.queries;
        stats.inclusion_boxes += t.boxes;
    }
    // A radix sort where the indices fit one word (stages/pair_order.hpp): on coplanar-stack,
    // half a million contacts an interval, the serial comparison sort was 9% of the samples
    // at one thread.
    sort_by_pair(result.contacts, [](const IntervalContact& c) -> const TrianglePair& { return c.pair; });
    for (const IntervalContact& c : result.contacts) {
        stats.pass_throughs += c.pass_through;
        stats.unresolved += !c.resolved;
    }
    stats.contacts = result.contacts.size();
    stats.narrow_ms = narrow.elapsed_ms();
    stats.ms = whole.elapsed_ms();
    return result;
}

}  // namespace collidescope
