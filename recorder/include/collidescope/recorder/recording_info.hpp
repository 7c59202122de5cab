#pragma once
/// What a recording holds besides its per-frame arrays: its objects and their topologies, a
/// per-frame series, a virtual dataset's mappings (read by Recording, reader.hpp).

#include "collidescope/between_frames.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace collidescope::recorder {

/// One topology of one object: triangles rows [first_row, first_row + triangle_count) of
/// /objects/<k>/triangles, in force from scene frame `from_frame`.
struct TopologyInfo {
    std::uint32_t from_frame = 0;
    std::uint32_t vertex_count = 0;
    std::uint64_t first_row = 0;
    std::uint64_t triangle_count = 0;
};

struct ObjectInfo {
    std::string name;
    std::vector<TopologyInfo> topologies;  ///< in order of from_frame
};

/// One region of one recorded frame (/regions, schema 1.5; docs/explanation/regions.md).
struct RecordedRegion {
    std::uint32_t id = 0;           ///< follows the region over frames, from 1
    std::uint32_t obj_a = 0;
    std::uint32_t obj_b = 0;        ///< == obj_a for self-contact
    std::uint32_t pairs = 0;
    std::uint32_t triangles_a = 0;  ///< colliding triangles on obj_a's side
    std::uint32_t triangles_b = 0;  ///< on obj_b's (self: 0)
    std::uint32_t loops = 0;        ///< closed curves
    double curve_length = 0;
    double coplanar_area = 0;
    double box[6] = {0, 0, 0, 0, 0, 0};  ///< min x y z, max x y z
    /// Schema 1.6 (NaN where not defined, and in older recordings): obj_a's surface area inside
    /// obj_b, obj_b's inside obj_a, and the penetration depth (regions.md).
    double inside_area_a = std::numeric_limits<double>::quiet_NaN();
    double inside_area_b = std::numeric_limits<double>::quiet_NaN();
    double depth = std::numeric_limits<double>::quiet_NaN();
    struct Curve {
        bool closed = false;
        std::vector<double> xyz;  ///< 3 per point
    };
    std::vector<Curve> curves;
    std::vector<std::uint32_t> predecessors;  ///< last frame's region ids it continues, strongest first
};

/// One interval between two recorded frames (/intervals, schema 1.7; record --between-frames;
/// docs/explanation/between-frames.md): what BetweenFrames::detect returned for it.
struct RecordedInterval {
    std::uint64_t row = 0;         ///< the row of its second frame (>= 1)
    std::uint32_t from_frame = 0;  ///< scene frame numbers of its two ends
    std::uint32_t to_frame = 0;
    IntervalStats stats;           ///< the tolerance, times and counts
    std::vector<IntervalContact> contacts;  ///< sorted by pair; empty when not asked for
};

/// A per-frame series (one dataset of /frames/ms, /frames/counts or a /frames details group).
template <class T>
struct Series {
    std::string name;
    std::string unit;
    std::vector<T> values;  ///< one per complete frame
};

/// One mapping of a virtual dataset (a virtual join, `join --virtual`, docs/how-to/mpi.md): rows
/// [first, first + rows) of `dataset` are rows [source_first, source_first + rows) of
/// `source_dataset` in the part file `file`.
struct VirtualSource {
    std::string dataset;
    std::string file;            ///< as the mapping stores it (relative to the recording's directory)
    std::string resolved;        ///< where it was found (HDF5's search: HDF5_VDS_PREFIX, then beside the recording)
    std::string source_dataset;
    std::uint64_t first = 0;
    std::uint64_t rows = 0;
    std::uint64_t source_first = 0;
};

}  // namespace collidescope::recorder
