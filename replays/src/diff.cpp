// replay_diff(): two recordings of the same scene side by side, frame by frame, the pairs each
// found that the other did not highlighted.

#include "collidescope/replays/replay.hpp"

#include "png.hpp"
#include "render_pool.hpp"
#include "replay_common.hpp"

#include "collidescope/error.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <map>
#include <mutex>

namespace collidescope::replays {
namespace {

/// Marks the frame's triangles: pairs both found colliding, pairs only this one found
/// only_here; everything else plain. Returns the number of pairs only this one found.
std::uint64_t mark_difference(FrameData& mine, const FrameData& theirs) {
    std::vector<TrianglePair> only;
    std::set_difference(mine.colliding.begin(), mine.colliding.end(), theirs.colliding.begin(),
                        theirs.colliding.end(), std::back_inserter(only));
    for (ObjectFrame& object : mine.objects) std::fill(object.states.begin(), object.states.end(), k_state_plain);
    auto mark = [&](const TrianglePair& pair, std::uint8_t state) {
        for (const auto& [object, triangle] : {std::pair{pair.obj_a, pair.tri_a}, std::pair{pair.obj_b, pair.tri_b}}) {
            if (object < mine.objects.size() && triangle < mine.objects[object].states.size()) {
                std::uint8_t& s = mine.objects[object].states[triangle];
                s = std::max(s, state);
            }
        }
    };
    for (const TrianglePair& pair : mine.colliding) mark(pair, k_state_colliding);
    for (const TrianglePair& pair : only) mark(pair, k_state_only_here);
    mine.only_here = only.size();
    return only.size();
}

struct DiffLayout {
    Rect legend;
    Rect left;
    Rect right;
};

DiffLayout diff_layout(int width, int height) {
    const int legend = std::clamp(height / 24, 18, 30);
    const int half = width / 2;
    return {{0, 0, width, legend}, {0, legend, half - 1, height - legend}, {half + 1, legend, width - half - 1, height - legend}};
}

void caption(const char* name, const Rect& rect, const FrameData& frame, const std::string& file) {
    ImGui::SetNextWindowPos(ImVec2(float(rect.x), float(rect.y)));
    ImGui::SetNextWindowSize(ImVec2(float(rect.w), ImGui::GetFontSize() * 3.4f));
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground);
    ImGui::Text("%s  frame %u  method %s", file.c_str(), frame.frame, frame.method.c_str());
    ImGui::Text("%zu colliding pairs, %llu found only here", frame.colliding.size(),
                static_cast<unsigned long long>(frame.only_here));
    ImGui::End();
}

void diff_legend(const Rect& rect) {
    ImGui::SetNextWindowPos(ImVec2(float(rect.x), float(rect.y)));
    ImGui::SetNextWindowSize(ImVec2(float(rect.w), float(rect.h)));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(ImGui::GetFontSize() * 0.5f, 2));
    ImGui::Begin("diff legend", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                             ImGuiWindowFlags_NoSavedSettings);
    for (const auto& [state, label] : {std::pair{k_state_colliding, "colliding in both"},
                                       std::pair{k_state_only_here, "colliding only in this recording"}}) {
        const std::array<float, 3> c = state_colour(state);
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float s = ImGui::GetFontSize();
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, at.y + 1), ImVec2(at.x + s, at.y + s),
                                                  ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1)));
        ImGui::Dummy(ImVec2(s, s));
        ImGui::SameLine();
        ImGui::Text("%s", label);
        ImGui::SameLine();
    }
    ImGui::Text("   left: a, right: b");
    ImGui::End();
    ImGui::PopStyleVar();
}

// Pairs only compare between recordings of one scene: same objects, same triangles.
void check_same_scene(const RecordingData& a, const RecordingData& b) {
    const std::string both = a.path() + " and " + b.path();
    if (a.object_count() != b.object_count()) {
        throw InputError(both + ": different numbers of objects (" + std::to_string(a.object_count()) + " and " +
                         std::to_string(b.object_count()) + "); --diff compares recordings of one scene");
    }
    const std::string scene_a = a.attribute("scene") + ":" + a.attribute("scene_preset");
    const std::string scene_b = b.attribute("scene") + ":" + b.attribute("scene_preset");
    if (scene_a != scene_b) {
        throw InputError(both + ": different scenes (" + scene_a + " and " + scene_b +
                         "); --diff compares recordings of one scene");
    }
}

std::filesystem::path diff_file(const std::filesystem::path& dir, std::uint32_t frame) {
    char name[48];
    std::snprintf(name, sizeof name, "diff_%04u.png", frame);
    return dir / name;
}

}  // namespace

ReplaySummary replay_diff(const std::filesystem::path& a, const std::filesystem::path& b, const ReplayOptions& options,
                          const FrameDone& frame_done) {
    RecordingData data_a(a);
    RecordingData data_b(b);
    const std::vector<std::uint64_t> rows_a = replay_rows(data_a, options);
    std::map<std::uint32_t, std::uint64_t> row_of_b;
    for (const std::uint64_t row : data_b.rows_in(options.frame_begin, options.frame_end)) row_of_b[data_b.indices()[row]] = row;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> rows;
    for (const std::uint64_t row : rows_a) {
        const auto it = row_of_b.find(data_a.indices()[row]);
        if (it != row_of_b.end()) rows.emplace_back(row, it->second);
    }
    if (rows.empty()) throw InputError(a.string() + " and " + b.string() + ": no scene frame recorded in both");
    check_same_scene(data_a, data_b);
    prepare_output_dir(options.output_dir);
    std::vector<std::uint64_t> just_a, just_b;
    for (const auto& [ra, rb] : rows) {
        just_a.push_back(ra);
        just_b.push_back(rb);
    }
    Bounds bounds = data_a.bounds(just_a);
    bounds.add(data_b.bounds(just_b));
    // A's up axis; --camera focus frames the whole scene here (each side's collisions differ).
    const CameraSpec camera = resolved_camera(options.camera, data_a);
    const DiffLayout layout = diff_layout(options.width, options.height);
    const unsigned layers = k_layer_meshes | k_layer_collisions;

    ReplaySummary summary;
    summary.files.resize(rows.size());
    std::mutex reader_lock;
    std::mutex done_lock;
    const auto start = std::chrono::steady_clock::now();
    summary.renderer = run_parallel(options.gl, options.threads, rows.size(), options.width, options.height,
                                    [&](RenderThread& thread, std::uint64_t i) {
        FrameData frame_a, frame_b;
        {
            const std::lock_guard<std::mutex> guard(reader_lock);
            frame_a = data_a.load(rows[i].first, i);
            frame_b = data_b.load(rows[i].second, i);
        }
        // mark_difference changes the states only, so frame_a's pairs still serve b's turn.
        const std::uint64_t only_a = mark_difference(frame_a, frame_b);
        const std::uint64_t only_b = mark_difference(frame_b, frame_a);
        thread.renderer->clear();
        thread.renderer->draw(frame_a, make_camera(camera, bounds, layout.left, i, rows.size()), layers, 0);
        thread.renderer->draw(frame_b, make_camera(camera, bounds, layout.right, i, rows.size()), layers, 1);
        thread.overlay->draw([&] {
            diff_legend(layout.legend);
            caption("a", layout.left, frame_a, data_a.path());
            caption("b", layout.right, frame_b, data_b.path());
        });
        const std::filesystem::path file = diff_file(options.output_dir, frame_a.frame);
        write_png(file, thread.renderer->read_rgba(), options.width, options.height);
        const std::lock_guard<std::mutex> guard(done_lock);
        summary.files[i] = file;
        summary.only_in_a += only_a;
        summary.only_in_b += only_b;
        if (i == 0) {
            for (const ObjectFrame& object : frame_a.objects) summary.triangles += object.triangles->size();
        }
        ++summary.frames;
        if (frame_done) frame_done(rows.size());
    });
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary.threads = render_threads(options.threads, rows.size());
    return summary;
}

}  // namespace collidescope::replays
