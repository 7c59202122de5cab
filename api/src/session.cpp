// Session: declared objects, one engine Pipeline, an optional recorder; step() hands the
// caller's positions to the frame it keeps (views of packed doubles, no copy; other layouts
// converted once), runs the pipeline and hands back the pairs.

#include "collidescope/session.hpp"

#include "frame_input.hpp"
#include "session_recording.hpp"

#include "collidescope/error.hpp"
#include "collidescope/pipeline.hpp"
#include "collidescope/regions.hpp"
#include "collidescope/stats_json.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace collidescope {
namespace {

AdaptivePolicy parse_policy(const std::string& name) {
    if (const std::optional<AdaptivePolicy> policy = option_value(k_adaptive_policy_names, name)) return *policy;
    std::string known;
    for (const OptionName<AdaptivePolicy>& entry : k_adaptive_policy_names) {
        known += (known.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw std::invalid_argument("unknown policy '" + name + "' (known: " + known + ")");
}

PipelineConfig pipeline_config(const SessionOptions& options) {
    PipelineConfig config;
    config.method = options.method;
    config.self_collision = options.self_collision;
    config.threads = options.threads;
    config.adaptive.policy = parse_policy(options.policy);
    return config;
}

// Empties a frame's vertices when it goes out of scope: the end of a step, by return or throw.
struct DropViews {
    Frame& frame;
    explicit DropViews(Frame& dropped) : frame(dropped) {}
    DropViews(const DropViews&) = delete;
    DropViews& operator=(const DropViews&) = delete;
    ~DropViews() {
        for (ObjectFrame& object : frame.objects) object.vertices = FrameVertices();
    }
};

}  // namespace

struct Session::Impl {
    SessionOptions options;
    Pipeline pipeline;
    std::vector<std::string> names;                  ///< per object, as declared
    /// Per object: triangles declared and not yet in force (all, before the first step; one
    /// object's after set_triangles). They take effect at the next step that succeeds.
    std::vector<std::optional<std::vector<TriIndices>>> pending;
    std::vector<std::uint32_t> topology_from;        ///< per object: frame its topology took effect
    /// Reused across steps. Its vertices view the caller's memory (or `converted`) only
    /// during step(); between steps they are empty, so no view outlives the caller's arrays.
    Frame frame;
    /// Per object: positions converted from float32 or strided input (capacity reused).
    std::vector<std::vector<Vec3>> converted;
    FrameResult result;
    StepStats step_stats;  ///< the flat part of result.stats (stats())
    std::vector<CollidingPair> pairs;
    std::unique_ptr<recorder::Recorder> recorder;
    RegionTracker tracker;
    std::vector<StepRegion> regions;  ///< SessionOptions::regions: the last step's
    bool closed = false;

    explicit Impl(SessionOptions options_in)
        : options(std::move(options_in)), pipeline(pipeline_config(options)) {}

    std::string label(std::uint32_t object) const { return api::object_label(object, names[object]); }
    void take_positions(std::span<const VertexView> positions);
    void start_recording_once();
    void find_regions();
};

// The step's regions, followed from the last step's, as plain data: the recorder's when it
// records them (it found them in the step already), else found here.
void Session::Impl::find_regions() {
    std::vector<Region> found;
    if (!recorder) {
        found = collidescope::find_regions(frame, result.colliding_pairs);
        tracker.update(result.stats.frame, found);
    }
    const std::vector<Region>& step_regions = recorder ? recorder->last_regions() : found;
    regions.clear();
    for (const Region& r : step_regions) {
        StepRegion out{r.id, r.obj_a, r.obj_b, r.pairs, static_cast<std::uint32_t>(r.triangles_a.size()),
                       static_cast<std::uint32_t>(r.triangles_b.size()), r.loops, r.curve_length, r.coplanar_area,
                       {r.box.min().x(), r.box.min().y(), r.box.min().z()},
                       {r.box.max().x(), r.box.max().y(), r.box.max().z()}, {}, r.predecessors,
                       r.inside_area_a, r.inside_area_b, r.depth};
        for (const IntersectionCurve& curve : r.curves) {
            StepCurve c{curve.closed, {}, curve.length};
            for (const Vec3& p : curve.points) c.points.push_back({p.x(), p.y(), p.z()});
            out.curves.push_back(std::move(c));
        }
        regions.push_back(std::move(out));
    }
}

// Pending triangles take effect with the positions they come with: their indices are
// checked against that vertex count, which then holds until the object's triangles change.
// Nothing is committed unless every object's positions were taken.
void Session::Impl::take_positions(std::span<const VertexView> positions) {
    const auto objects = static_cast<std::uint32_t>(names.size());
    if (positions.size() != objects) {
        throw InputError("step: positions for " + std::to_string(positions.size()) + " objects, " +
                         std::to_string(objects) + " declared");
    }
    for (std::uint32_t k = 0; k < objects; ++k) {
        if (pending[k]) {
            if (positions[k].count > UINT32_MAX) throw InputError(label(k) + ": more than 2^32-1 vertices");
            api::check_triangle_indices(*pending[k], static_cast<std::uint32_t>(positions[k].count), label(k));
        } else if (positions[k].count != frame.objects[k].topology->vertex_count) {
            throw InputError(label(k) + ": " + std::to_string(positions[k].count) + " vertices in frame " +
                             std::to_string(frame.index) + ", " +
                             std::to_string(frame.objects[k].topology->vertex_count) + " since frame " +
                             std::to_string(topology_from[k]) + " (set_triangles changes an object's topology)");
        }
    }
    frame.objects.resize(objects);
    converted.resize(objects);
    frame.positions_copied_bytes = 0;
    for (std::uint32_t k = 0; k < objects; ++k) {
        frame.positions_copied_bytes +=
            api::take_vertices(positions[k], converted[k], frame.objects[k].vertices, label(k));
    }
    for (std::uint32_t k = 0; k < objects; ++k) {
        if (!pending[k]) continue;
        auto topology = std::make_shared<Topology>();
        topology->triangles = std::move(*pending[k]);
        topology->vertex_count = static_cast<std::uint32_t>(positions[k].count);
        topology->revision = next_topology_revision();
        frame.objects[k].topology = std::move(topology);
        topology_from[k] = frame.index;
        pending[k].reset();
    }
}

// With options.record, the recorder starts at the first frame taken (its chunks are sized by
// it) and reports every frame from then on; unnamed objects are "object<k>" in the file.
void Session::Impl::start_recording_once() {
    if (options.record.empty() || recorder) return;
    std::vector<std::string> file_names = names;
    for (std::size_t k = 0; k < file_names.size(); ++k) {
        if (file_names[k].empty()) file_names[k] = "object" + std::to_string(k);
    }
    recorder = api::start_recording(options, pipeline.config(), std::move(file_names), frame);
    pipeline.add_sink(*recorder);
}

Session::Session(SessionOptions options) : m_impl(std::make_unique<Impl>(std::move(options))) {}

Session::~Session() {
    if (!m_impl) return;
    try {
        close();
    } catch (...) {
        // A destructor must not throw; close() reports write failures to callers that ask.
    }
}

Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;

std::uint32_t Session::add_object(std::span<const std::array<std::uint32_t, 3>> triangles, std::string name) {
    if (m_impl->frame.index > 0 || m_impl->closed) {
        throw std::logic_error("add_object: objects are declared before the first step");
    }
    const auto object = static_cast<std::uint32_t>(m_impl->names.size());
    if (triangles.empty()) throw InputError(api::object_label(object, name) + ": no triangles");
    m_impl->names.push_back(std::move(name));
    m_impl->pending.emplace_back(std::vector<TriIndices>(triangles.begin(), triangles.end()));
    m_impl->topology_from.push_back(0);
    return object;
}

void Session::set_triangles(std::uint32_t object, std::span<const std::array<std::uint32_t, 3>> triangles) {
    if (object >= m_impl->names.size()) {
        throw InputError("set_triangles: no object " + std::to_string(object) + " (" +
                         std::to_string(m_impl->names.size()) + " declared)");
    }
    if (triangles.empty()) throw InputError(m_impl->label(object) + ": no triangles");
    m_impl->pending[object].emplace(triangles.begin(), triangles.end());
}

std::uint32_t Session::add_object(std::span<const std::uint32_t> triangles, std::string name) {
    if (triangles.size() % 3 != 0) {
        throw InputError("add_object: " + std::to_string(triangles.size()) + " indices, not 3 per triangle");
    }
    static_assert(sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::uint32_t));
    const auto* first = reinterpret_cast<const std::array<std::uint32_t, 3>*>(triangles.data());
    return add_object(std::span(first, triangles.size() / 3), std::move(name));
}

std::span<const CollidingPair> Session::step(std::span<const VertexView> positions) {
    Impl& impl = *m_impl;
    if (impl.closed) throw std::logic_error("step: the session is closed");
    if (impl.names.empty()) throw InputError("step: no objects declared (add_object before the first step)");
    // The frame views the caller's memory from here until the step ends, however it ends
    // (the pipeline and its sinks read it only inside process(); the recorder copies the
    // positions to float32 there, the background rebuild takes its own copy).
    const DropViews drop_views{impl.frame};
    impl.take_positions(positions);
    impl.start_recording_once();
    impl.result = impl.pipeline.process(impl.frame);
    impl.step_stats = {impl.result.stats.frame, impl.result.stats.method, impl.result.stats.ms, impl.result.stats.counts};
    ++impl.frame.index;
    if (impl.options.regions) impl.find_regions();
    impl.pairs.resize(impl.result.colliding_pairs.size());
    std::transform(impl.result.colliding_pairs.begin(), impl.result.colliding_pairs.end(), impl.pairs.begin(),
                   [](const TrianglePair& p) { return CollidingPair{p.obj_a, p.tri_a, p.obj_b, p.tri_b}; });
    return impl.pairs;
}

const StepStats& Session::stats() const { return m_impl->step_stats; }
std::span<const StepRegion> Session::regions() const { return m_impl->regions; }
std::string Session::stats_json() const { return collidescope::stats_json(m_impl->result.stats); }
std::uint32_t Session::frame_count() const { return m_impl->frame.index; }
std::uint32_t Session::object_count() const { return static_cast<std::uint32_t>(m_impl->names.size()); }
const SessionOptions& Session::options() const { return m_impl->options; }

void Session::close() {
    Impl& impl = *m_impl;
    if (impl.closed) return;
    impl.closed = true;
    if (impl.recorder) impl.recorder->finish();
}

}  // namespace collidescope
