// open_inputs: the command line's inputs (mesh files, frame patterns, scene.json manifests)
// as one scene over a lazily reading FileSource.
//
// Manifest format: {"name": str, "frames": F, "objects": [{"name": str, "pattern": str}],
// "self": bool}. Only "objects" and each object's "pattern" are required; "name" defaults to
// the manifest's directory name (objects: the pattern's name), "self" to false. An object may
// say "mesh" instead of "pattern", and with it "cache": a point cache (.pc2, .mdd) whose frames
// move the mesh's vertices (docs/how-to/point-caches.md). Paths are relative to the manifest's
// directory. When "frames" is given the scene uses the first F frames of every sequence or
// cache (a manifest may describe part of a longer cache); one with fewer than F frames is an
// error. Without it, the frames found are used.
//
// A mesh file that assimp reads with animation (not .ply, .obj or .gz) is an animated model:
// one object per mesh instance, posed per frame (scene/animated_file.hpp). A manifest may give
// "fps" (a positive number) and "clip" (a name or an index) at its top level for the animated
// files it lists; the command line's --fps / --clip win over them. "frames" does not shorten
// an animated file (use --frames).

#include "mesh/format_extension.hpp"
#include "scene/animated_file.hpp"
#include "scene/mesh_with_point_cache.hpp"
#include "scene/file_source.hpp"
#include "scene/frame_pattern.hpp"

#include "mesh/animated_model.hpp"

#include "collidescope/error.hpp"
#include "collidescope/scene.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>

namespace collidescope {
namespace {

/// What the inputs add up to, before the FileSource is made.
struct SceneInputs {
    std::vector<FileObject> objects;
    std::optional<std::string> manifest_name;
    bool self_collision = false;
    std::shared_ptr<AnimatedFile> first_animated;  ///< says the scene's fps, clip and frame times
    char up_axis = 0;                              ///< the first file's that says one
};

// Probing imports the file once more than a static mesh needs, so formats that cannot hold an
// animation (our own readers' PLY and OBJ; STL, OFF) and gzipped files are not probed.
bool may_be_animated(const std::filesystem::path& path) {
    const std::string extension = lowercase(path.extension().string());
    for (const char* still : {".ply", ".obj", ".gz", ".stl", ".off"}) {
        if (extension == still) return false;
    }
    return true;
}

// A mesh file (static) or a frame pattern (one file per frame), named `name` or after the file.
FileObject open_object(const std::string& spec, const std::string& name) {
    if (const std::optional<CacheSpec> cached = parse_cache_spec(spec)) {
        return open_mesh_with_point_cache(cached->mesh, cached->cache, name);
    }
    FileObject object;
    object.origin = spec;
    const std::filesystem::path path(spec);
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error)) {
        object.is_static = true;
        object.files = {path};
    } else if (const std::optional<FramePattern> pattern = parse_frame_pattern(spec)) {
        object.files = expand_frame_pattern(*pattern, spec);
    } else if (std::filesystem::is_directory(path, error)) {
        throw InputError(spec + ": is a directory, expected a mesh file, a frame pattern or a scene.json");
    } else {
        throw InputError(spec + ": no such file");
    }
    object.name = name.empty() ? object_name_from(path.filename().string()) : name;
    return object;
}

// An input: an animated model file (one object per mesh instance, named "<node>/<mesh>",
// prefixed by `name` when one is given) or what open_object makes of it.
std::vector<FileObject> open_objects(const std::string& spec, const std::string& name,
                                     const AnimationOptions& animation, SceneInputs& inputs) {
    const std::filesystem::path path(spec);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) || !may_be_animated(path)) return {open_object(spec, name)};
    animation::AnimatedModel model = animation::read_animated_model(path, /*only_if_animated=*/true);
    if (inputs.up_axis == 0) inputs.up_axis = model.up_axis;
    if (model.clips.empty()) return {open_object(spec, name)};
    auto file = std::make_shared<AnimatedFile>(path, std::move(model), animation);
    if (!inputs.first_animated) inputs.first_animated = file;
    std::vector<FileObject> objects;
    for (std::uint32_t i = 0; i < file->instance_count(); ++i) {
        FileObject object;
        object.origin = spec;
        object.name = (name.empty() ? "" : name + "/") + file->instance_name(i);
        object.animated = file;
        object.instance = i;
        objects.push_back(std::move(object));
    }
    return objects;
}

// Reads a manifest's JSON and checks the keys one by one, naming the first bad one.
class ManifestReader {
public:
    // In the class, not at file scope: a unity batch shares the file scope with its other files.
    using json = nlohmann::json;

    ManifestReader(const std::filesystem::path& file, const AnimationOptions& animation)
        : m_file(file), m_animation(animation) {}

    void read(SceneInputs& inputs) {
        const json doc = parse();
        if (!doc.is_object()) fail("", "expected a JSON object at the top level");
        const std::optional<std::string> name = optional_string(doc, "name", "name");
        const std::optional<std::uint32_t> frames = optional_frames(doc);
        read_animation_options(doc);
        if (const json* self = find(doc, "self")) {
            if (!self->is_boolean()) wrong_type("self", "a boolean", *self);
            inputs.self_collision = inputs.self_collision || self->get<bool>();
        }
        const json* objects = find(doc, "objects");
        if (objects == nullptr) fail("objects", "missing key");
        if (!objects->is_array() || objects->empty()) wrong_type("objects", "a non-empty array", *objects);
        for (std::size_t i = 0; i < objects->size(); ++i) read_object((*objects)[i], i, frames, inputs);
        if (!inputs.manifest_name) inputs.manifest_name = name.value_or(default_name());
    }

private:
    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw InputError(m_file.string() + ": " + (key.empty() ? "" : key + ": ") + what);
    }

    [[noreturn]] void wrong_type(const std::string& key, const std::string& expected,
                                 const json& value) const {
        fail(key, "expected " + expected + ", got " + value.type_name() + " " + value.dump());
    }

    json parse() const {
        const std::vector<std::byte> bytes = read_file_bytes(m_file);
        const char* text = reinterpret_cast<const char*>(bytes.data());
        try {
            return json::parse(text, text + bytes.size());
        } catch (const json::exception& error) {
            fail("", std::string("malformed JSON (") + error.what() + ")");
        }
    }

    static const json* find(const json& object, const char* key) {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    std::optional<std::string> optional_string(const json& object, const char* key,
                                               const std::string& path) const {
        const json* value = find(object, key);
        if (value == nullptr) return std::nullopt;
        if (!value->is_string()) wrong_type(path, "a string", *value);
        return value->get<std::string>();
    }

    std::optional<std::uint32_t> optional_frames(const json& doc) const {
        const json* frames = find(doc, "frames");
        if (frames == nullptr) return std::nullopt;
        const bool positive = frames->is_number_unsigned() && frames->get<std::uint64_t>() > 0 &&
                              frames->get<std::uint64_t>() <= std::numeric_limits<std::uint32_t>::max();
        if (!positive) wrong_type("frames", "a positive integer", *frames);
        return frames->get<std::uint32_t>();
    }

    // Top-level "fps" and "clip", where the command line leaves them unset.
    void read_animation_options(const json& doc) {
        if (const json* fps = find(doc, "fps"); fps != nullptr && !m_animation.fps) {
            if (!fps->is_number() || !(fps->get<double>() > 0)) wrong_type("fps", "a positive number", *fps);
            m_animation.fps = fps->get<double>();
        }
        if (const json* clip = find(doc, "clip"); clip != nullptr && !m_animation.clip) {
            if (clip->is_string()) {
                m_animation.clip = clip->get<std::string>();
            } else if (clip->is_number_unsigned()) {
                m_animation.clip = std::to_string(clip->get<std::uint64_t>());
            } else {
                wrong_type("clip", "a clip name or index", *clip);
            }
        }
    }

    void read_object(const json& entry, std::size_t index, std::optional<std::uint32_t> frames,
                     SceneInputs& inputs) const {
        const std::string path = "objects[" + std::to_string(index) + "]";
        if (!entry.is_object()) wrong_type(path, "an object", entry);
        const std::optional<std::string> pattern = optional_string(entry, "pattern", path + ".pattern");
        const std::optional<std::string> mesh = optional_string(entry, "mesh", path + ".mesh");
        const std::optional<std::string> cache = optional_string(entry, "cache", path + ".cache");
        if (pattern && mesh) fail(path, "give either \"pattern\" or \"mesh\", not both");
        if (!pattern && !mesh) fail(path + ".pattern", "missing key (or \"mesh\")");
        if (cache && !mesh) fail(path + ".cache", "needs \"mesh\": the mesh file whose vertices the cache moves");
        const std::string name = optional_string(entry, "name", path + ".name").value_or("");
        const std::filesystem::path spec = m_file.parent_path() / (pattern ? *pattern : *mesh);
        if (cache) {
            FileObject object = open_mesh_with_point_cache(spec.string(), (m_file.parent_path() / *cache).string(), name);
            if (frames) use_frames(object, *frames);
            inputs.objects.push_back(std::move(object));
            return;
        }
        for (FileObject& object : open_objects(spec.string(), name, m_animation, inputs)) {
            if (frames && !object.is_static && !object.animated) use_frames(object, *frames);
            inputs.objects.push_back(std::move(object));
        }
    }

    void use_frames(FileObject& object, std::uint32_t frames) const {
        if (object.frame_count() < frames) {
            fail("frames", "asks for " + std::to_string(frames) + " frames but object '" +
                               object.name + "' (" + object.origin + ") has " +
                               std::to_string(object.frame_count()));
        }
        if (object.cache) {
            object.cache_frames = frames;
        } else {
            object.files.resize(frames);
        }
    }

    std::string default_name() const {
        const std::string directory = std::filesystem::absolute(m_file).parent_path().filename().string();
        return directory.empty() ? object_name_from(m_file.filename().string()) : directory;
    }

    std::filesystem::path m_file;
    AnimationOptions m_animation;  ///< the command line's, completed by the manifest's
};

bool is_manifest(const std::string& input) {
    return lowercase(std::filesystem::path(input).extension().string()) == ".json";
}

// The frame count all sequences share (1 when every object is static).
std::uint32_t common_frame_count(const std::vector<FileObject>& objects) {
    const FileObject* first = nullptr;
    for (const FileObject& object : objects) {
        if (object.is_static) continue;
        if (first == nullptr) {
            first = &object;
        } else if (object.frame_count() != first->frame_count()) {
            throw InputError("objects '" + first->name + "' (" + first->origin + ": " +
                             std::to_string(first->frame_count()) + " frames) and '" + object.name +
                             "' (" + object.origin + ": " + std::to_string(object.frame_count()) +
                             " frames) have different frame counts");
        }
    }
    if (first == nullptr) return 1;
    if (first->frame_count() > std::numeric_limits<std::uint32_t>::max()) {
        throw InputError(first->origin + ": too many frames");
    }
    return static_cast<std::uint32_t>(first->frame_count());
}

// The time of each frame, from the first point cache among the objects (their frames are the
// scene's frames); nothing when no object has one.
void take_cache_times(const std::vector<FileObject>& objects, std::uint32_t frames, Scene& scene) {
    for (const FileObject& object : objects) {
        if (!object.cache) continue;
        const PointCacheLayout& layout = object.cache->layout();
        scene.frame_times.assign(layout.frame_times.begin(), layout.frame_times.begin() + frames);
        scene.fps = layout.fps;
        return;
    }
}

std::string scene_name(const SceneInputs& inputs) {
    if (inputs.manifest_name) return *inputs.manifest_name;
    std::string name;
    const AnimatedFile* last_file = nullptr;
    for (const FileObject& object : inputs.objects) {
        // An animated file's instances are named once, after the file.
        if (object.animated && object.animated.get() == last_file) continue;
        const std::string part = object.animated ? object_name_from(std::filesystem::path(object.origin).filename().string())
                                                 : object.name;
        last_file = object.animated.get();
        name += (name.empty() ? "" : "+") + part;
    }
    return name;
}

}  // namespace

Scene open_inputs(std::span<const std::string> inputs, const AnimationOptions& animation) {
    if (inputs.empty()) throw InputError("no input given (a mesh file, frame pattern or scene.json)");
    SceneInputs collected;
    for (const std::string& input : inputs) {
        if (is_manifest(input)) {
            ManifestReader(input, animation).read(collected);
        } else {
            for (FileObject& object : open_objects(input, "", animation, collected)) {
                collected.objects.push_back(std::move(object));
            }
        }
    }
    const std::uint32_t frames = common_frame_count(collected.objects);
    Scene scene;
    scene.name = scene_name(collected);
    scene.self_collision = collected.self_collision;
    take_cache_times(collected.objects, frames, scene);
    scene.up_axis = collected.up_axis;
    if (collected.first_animated) {
        scene.fps = collected.first_animated->fps();
        scene.clip = collected.first_animated->clip_name();
        scene.frame_times = collected.first_animated->frame_times();
    }
    scene.source = make_file_source(std::move(collected.objects), frames);
    return scene;
}

}  // namespace collidescope
