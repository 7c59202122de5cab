#pragma once
/// The recording's HDF5 schema in one place: the version, every group and dataset name and
/// every unit. docs/reference/recording.md describes the same layout for h5py and h5dump users.
///
/// Per-frame datasets are 1-D (or rows of a flat array) and extensible along the frame axis;
/// row r of every per-frame dataset is recorded frame r, whose scene frame number is
/// /frames/index[r]. Flat arrays (pairs, positions, triangles) are indexed through CSR offsets
/// with one more entry than rows (offsets[0] == 0). No variable-length types in datasets.

#include <cstdint>
#include <string>

namespace collidescope::recorder::schema {

/// Value of the root attribute `schema`: says the file is a collidescope recording.
inline constexpr const char* k_schema_name = "collidescope-trace";
/// Major: readers refuse files with a newer major (layout changed incompatibly). Minor: only
/// additions (new datasets or attributes); older readers ignore what they do not know.
inline constexpr std::int64_t k_version_major = 1;
/// 1.1: /frames/gpu, /frames/aabb, /gpu. 1.2: /frames/decision, /frames/hybrid, /gpu/survivors,
/// /gpu/depth; string attributes fixed-length (1.0 and 1.1 wrote variable-length ones).
/// 1.3: the root attribute `interrupted` (a run stopped early by a signal).
/// 1.4: /frames/time and the root attributes `fps`, `clip`, `up_axis`, each only when the
/// scene's inputs say them (animated models, point caches); absent otherwise.
/// 1.5: /regions and the root attribute `regions`, only in recordings made with `--regions`.
/// 1.6: /regions/penetration (inside areas and depth), with /regions.
/// 1.7: /intervals and the root attributes `between_frames` and `ccd_tolerance`, only in
/// recordings made with `--between-frames`.
inline constexpr std::int64_t k_version_minor = 7;

// Root attributes.
inline constexpr const char* k_attr_schema = "schema";
inline constexpr const char* k_attr_version_major = "schema_version_major";
inline constexpr const char* k_attr_version_minor = "schema_version_minor";
inline constexpr const char* k_attr_finished = "finished";  ///< 1 once closed cleanly (absent until then)
inline constexpr const char* k_attr_frames_recorded = "frames_recorded";  ///< set with `finished`
inline constexpr const char* k_attr_positions_stride = "positions_stride";  ///< set with `finished`
/// Set with `finished` when the run stopped before its last frame: the signal ("SIGINT",
/// "SIGTERM") that stopped it; the file then holds fewer frames than frame_begin..frame_end.
inline constexpr const char* k_attr_interrupted = "interrupted";
/// Every dataset's unit, H5MD style: a string attribute named `unit`.
inline constexpr const char* k_attr_unit = "unit";
/// Frames per second of the source animation's sampling (float64; only when the inputs say). 1.4.
inline constexpr const char* k_attr_fps = "fps";
/// The source animation clip's name (string; only when the inputs name one). 1.4.
inline constexpr const char* k_attr_clip = "clip";
/// The axis the inputs call up: "x", "y" or "z" (string; only when a file says). 1.4.
inline constexpr const char* k_attr_up_axis = "up_axis";
/// On each /objects/<k> group: the object's name.
inline constexpr const char* k_attr_name = "name";

// Groups and datasets.
inline constexpr const char* k_frames = "/frames";
inline constexpr const char* k_frame_index = "/frames/index";    ///< uint32, scene frame number
/// float64, seconds from the clip's start of each recorded frame (unit "s"); only when the
/// scene's inputs carry time. 1.4.
inline constexpr const char* k_frame_time = "/frames/time";
inline constexpr const char* k_frame_method = "/frames/method";  ///< enum (uint8) of method names
inline constexpr const char* k_frame_ms = "/frames/ms";          ///< group: float64 per stage
inline constexpr const char* k_frame_counts = "/frames/counts";  ///< group: uint64 per count
/// Group: float64 per GpuFrameInfo scalar (for_each_gpu_value), plus uint8 `present` (1 when
/// the frame's method ran the GPU cull; the other columns are 0 otherwise). Schema 1.1.
inline constexpr const char* k_frame_gpu = "/frames/gpu";
/// Group: float64 per AabbFrameInfo field (for_each_aabb_value), plus uint8 `present`. 1.1.
inline constexpr const char* k_frame_aabb = "/frames/aabb";
/// Group: float64 per DecisionInfo field (for_each_decision_value), plus uint8 `present`. 1.2.
inline constexpr const char* k_frame_decision = "/frames/decision";
/// Group: float64 per HybridFrameInfo field (for_each_hybrid_value), plus uint8 `present`. 1.2.
inline constexpr const char* k_frame_hybrid = "/frames/hybrid";
inline constexpr const char* k_present = "present";
inline constexpr const char* k_gpu = "/gpu";
/// (N, 8) uint64: one row per cull pass (for_each_pass_field order). 1.1.
inline constexpr const char* k_gpu_passes = "/gpu/passes";
inline constexpr const char* k_gpu_pass_offsets = "/gpu/pass_offsets";  ///< (F + 1) uint64
/// (S, 2) uint32: (object, triangle) of each triangle left in the PCS after the cull. 1.2.
inline constexpr const char* k_gpu_survivors = "/gpu/survivors";
inline constexpr const char* k_gpu_survivor_offsets = "/gpu/survivor_offsets";  ///< (F + 1) uint64
/// The cull's depth buffers (--depth every:N), one row per image in the image table. 1.2.
inline constexpr const char* k_gpu_depth = "/gpu/depth";
inline constexpr const char* k_depth_image_offsets = "/gpu/depth/image_offsets";  ///< (F + 1) uint64
/// (I, 4) uint32 per image: level (0 objects, 1 triangles), view axis, width, height.
inline constexpr const char* k_depth_info = "/gpu/depth/info";
/// (I, 2) float64 per image: the world coordinates along the view axis of window depth 0 and 1.
inline constexpr const char* k_depth_range = "/gpu/depth/range";
inline constexpr const char* k_depth_pixel_offsets = "/gpu/depth/pixel_offsets";  ///< (I + 1) uint64
/// Flat uint16: every image's pixels, row-major, bottom row first; q / 65535 is the window depth,
/// 65535 exactly where nothing was drawn (depth 1; drawn pixels round to at most 65534).
inline constexpr const char* k_depth_pixels = "/gpu/depth/pixels";
/// Quantisation of depth pixels: depth = q / k_depth_scale.
inline constexpr double k_depth_scale = 65535.0;
inline constexpr const char* k_collisions = "/collisions";
inline constexpr const char* k_pairs = "/collisions/pairs";           ///< (P, 4) uint32
inline constexpr const char* k_pair_offsets = "/collisions/offsets";  ///< (F + 1) uint64
/// Interpenetration regions (record --regions; schema 1.5): three CSR levels, frames to
/// regions to curves to points, plus each region's predecessors (docs/explanation/regions.md).
inline constexpr const char* k_regions = "/regions";
inline constexpr const char* k_region_offsets = "/regions/offsets";  ///< (F + 1) uint64 into table rows
/// (R, 7) uint32 per region: id, obj_a, obj_b, pairs, triangles_a, triangles_b, loops.
inline constexpr const char* k_region_table = "/regions/table";
/// (R, 8) float64 per region: curve_length, coplanar_area, box min x y z, box max x y z.
inline constexpr const char* k_region_measures = "/regions/measures";
/// (R, 3) float64 per region (schema 1.6): inside_area_a, inside_area_b, depth, NaN where not
/// defined (regions.md). Absent from 1.5 recordings, whose regions read NaN there.
inline constexpr const char* k_region_penetration = "/regions/penetration";
inline constexpr const char* k_region_curve_offsets = "/regions/curve_offsets";  ///< (R + 1) uint64
inline constexpr const char* k_region_curve_closed = "/regions/curve_closed";    ///< (C) uint8
inline constexpr const char* k_region_point_offsets = "/regions/point_offsets";  ///< (C + 1) uint64
inline constexpr const char* k_region_points = "/regions/points";                ///< (Q, 3) float64
/// (R + 1) uint64 into predecessors.
inline constexpr const char* k_region_predecessor_offsets = "/regions/predecessor_offsets";
/// (K) uint32: ids of the previous frame's regions each region continues, strongest first.
inline constexpr const char* k_region_predecessors = "/regions/predecessors";
/// Root attribute: 1 when the recording holds /regions (absent otherwise).
inline constexpr const char* k_attr_regions = "regions";
/// Between the frames (record --between-frames; schema 1.7; docs/explanation/between-frames.md):
/// row r holds the interval from recorded frame r - 1 to frame r (row 0: none, zeros and NaN).
inline constexpr const char* k_intervals = "/intervals";
inline constexpr const char* k_interval_offsets = "/intervals/offsets";  ///< (F + 1) uint64 into the contact rows
/// (F, 7) uint64 per interval: candidate_pairs, start_contacts, primitive_queries,
/// inclusion_boxes, contacts, pass_throughs, unresolved (IntervalStats).
inline constexpr const char* k_interval_counts = "/intervals/counts";
/// (F, 3) float64 per interval: broad, narrow and total ms.
inline constexpr const char* k_interval_ms = "/intervals/ms";
/// (F) float64: the tolerance δ the interval was decided with (NaN in row 0).
inline constexpr const char* k_interval_tolerance = "/intervals/tolerance";
inline constexpr const char* k_interval_pairs = "/intervals/pairs";  ///< (P, 4) uint32: obj_a tri_a obj_b tri_b
/// (P) float64: a lower bound of each pair's first time of contact in [0, 1].
inline constexpr const char* k_interval_toi = "/intervals/toi";
/// (P) uint8 per pair: bit 0 pass-through (apart at both frames), bit 1 unresolved.
inline constexpr const char* k_interval_flags = "/intervals/flags";
inline constexpr std::uint8_t k_flag_pass_through = 1;
inline constexpr std::uint8_t k_flag_unresolved = 2;
/// Root attribute: 1 when the recording holds /intervals (absent otherwise).
inline constexpr const char* k_attr_between_frames = "between_frames";
/// Root attribute: the --ccd-tolerance asked for (0: automatic, per interval).
inline constexpr const char* k_attr_ccd_tolerance = "ccd_tolerance";
inline constexpr const char* k_objects = "/objects";
// Inside /objects/<k>/ (k = 0, 1, ... in input order):
inline constexpr const char* k_triangles = "triangles";                  ///< (T, 3) uint32
inline constexpr const char* k_topology_offsets = "topology_offsets";    ///< (R + 1) uint64
inline constexpr const char* k_topology_from_frame = "topology_from_frame";  ///< (R) uint32
inline constexpr const char* k_topology_vertex_count = "topology_vertex_count";  ///< (R) uint32
inline constexpr const char* k_positions = "positions";             ///< (N, 3) float32
inline constexpr const char* k_vertex_offsets = "vertex_offsets";   ///< (F + 1) uint64

// Units.
inline constexpr const char* k_unit_ms = "ms";
inline constexpr const char* k_unit_seconds = "s";
/// Dimensionless: counts, indices, offsets (UDUNITS' "1").
inline constexpr const char* k_unit_none = "1";
/// Vertex positions keep the input's coordinates; their length unit is whatever the input used.
inline constexpr const char* k_unit_length = "input length unit";

/// "/objects/<k>".
inline std::string object_group(std::uint32_t object) {
    return std::string(k_objects) + "/" + std::to_string(object);
}

}  // namespace collidescope::recorder::schema
