#pragma once
// Frames read from mesh files, lazily (engine/src/scene, private).
//
// open_inputs turns the command line into FileObjects; the FileSource reads frame i's files
// when frame(i) is asked for. A static object's file is read once and repeated every frame.
// A cached object's mesh is read once for its triangles, and frame i's positions come from
// its point cache.

#include "collidescope/point_cache.hpp"
#include "collidescope/scene.hpp"

#include "scene/animated_file.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace collidescope {

/// One object of a file scene.
struct FileObject {
    std::string name;                          ///< object name (file stem, pattern without number)
    std::string origin;                        ///< the file or pattern as given, for messages
    std::vector<std::filesystem::path> files;  ///< one per frame; exactly one when is_static
    bool is_static = false;                    ///< the same mesh in every frame
    /// A mesh + point cache object: `files` holds the mesh alone (is_static false) and the
    /// cache's first `cache_frames` frames are the object's frames.
    std::shared_ptr<PointCacheReader> cache;
    std::uint32_t cache_frames = 0;

    /// How many frames the object has (1 for a static mesh; an animated instance: its clip's).
    std::size_t frame_count() const;
    /// A mesh instance of an animated model file (files empty, is_static false): its frames
    /// are posed by `animated`, which the file's other instances share.
    std::shared_ptr<AnimatedFile> animated;
    std::uint32_t instance = 0;                ///< the instance within `animated`
};

/// A FrameSource over `objects` with `frame_count` frames (every sequence object holds at
/// least that many files). Each frame's meshes are read and validated on demand; a frame whose
/// triangles equal the object's previous ones shares that Topology (same revision).
std::shared_ptr<FrameSource> make_file_source(std::vector<FileObject> objects,
                                              std::uint32_t frame_count);

}  // namespace collidescope
