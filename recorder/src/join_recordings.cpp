// `join`: recordings of contiguous frame ranges of one session -> one recording (join.hpp).

#include "collidescope/recorder/join.hpp"

#include "h5.hpp"
#include "join_copy.hpp"
#include "join_virtual.hpp"
#include "virtual_sources.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/schema.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <system_error>

namespace collidescope::recorder {
namespace {

// Root attributes that say how and when one part was made, not what it holds: they may
// differ between parts. The output keeps the first part's, except the frame range (both
// ends) and the ones written when it is finished.
const std::set<std::string> k_per_run = {"created",         "hardware_threads", "threads",
                                         "gl_renderer",     schema::k_attr_finished,
                                         schema::k_attr_frames_recorded, schema::k_attr_positions_stride,
                                         schema::k_attr_interrupted, "frame_begin", "frame_end"};
const std::set<std::string> k_written_at_finish = {schema::k_attr_finished, schema::k_attr_frames_recorded,
                                                   schema::k_attr_positions_stride, schema::k_attr_interrupted};

struct Node {
    std::string path;
    bool group = false;
};

// Rows of one dataset a part contributes: [begin, end); an offsets dataset's values lose
// `base` (the value at begin - 1) before the output's running end is added.
struct Rows {
    hsize_t begin = 0;
    hsize_t end = 0;
    std::uint64_t base = 0;
};

struct Part {
    std::filesystem::path path;
    h5::Where where{""};
    h5::Id file;
    std::uint64_t frames = 0;       ///< complete frames
    bool complete = false;          ///< finished, not interrupted, every requested frame
    std::uint32_t first = 0, last = 0;  ///< scene frame numbers of the first and last complete frame
    std::int64_t frame_begin = 0, frame_end = 0;
    std::map<std::string, Rows> rows;
};

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}
std::string leaf(const std::string& path) { return path.substr(path.rfind('/') + 1); }
bool is_offsets(const std::string& path) { return ends_with(leaf(path), "offsets"); }
bool is_topology_offsets(const std::string& path) { return leaf(path) == schema::k_topology_offsets; }

h5::Id open_part_file(const h5::Where& where) {
    const std::string& path = where.file();
    hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT);
    if (id < 0) id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    return where.own(id, H5Fclose, "cannot open the HDF5 file");
}

void walk(const h5::Where& where, hid_t file, const std::string& group, std::vector<Node>& out) {
    const h5::Id handle = h5::open_group(where, file, group);
    for (const std::string& name : h5::member_names(where, handle.get(), group)) {
        const std::string path = (group == "/" ? "/" : group + "/") + name;
        const h5::Id object = where.own(H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + path);
        const H5I_type_t type = H5Iget_type(object.get());
        if (type == H5I_GROUP) {
            out.push_back({path, true});
            walk(where, file, path, out);
        } else if (type == H5I_DATASET) {
            out.push_back({path, false});
        } else {
            where.fail(path + ": neither a group nor a dataset (join copies only those)");
        }
    }
}

std::uint64_t read_u64(const Part& part, const std::string& path, hsize_t row) {
    const h5::Id dataset = h5::open_dataset(part.where, part.file.get(), path);
    std::uint64_t value = 0;
    h5::read_rows(part.where, dataset.get(), path, H5T_NATIVE_UINT64, row, 1, &value);
    return value;
}

std::vector<std::uint32_t> read_u32(const Part& part, const std::string& path, hsize_t first, hsize_t rows) {
    const h5::Id dataset = h5::open_dataset(part.where, part.file.get(), path);
    const std::vector<hsize_t> dims = h5::shape(part.where, dataset.get(), path);
    const hsize_t width = dims.size() == 2 ? dims[1] : 1;
    std::vector<std::uint32_t> values(rows * width);
    h5::read_rows(part.where, dataset.get(), path, H5T_NATIVE_UINT32, first, rows, values.data());
    return values;
}

hsize_t length_of(const Part& part, const std::string& path) {
    const h5::Id dataset = h5::open_dataset(part.where, part.file.get(), path);
    const std::vector<hsize_t> dims = h5::shape(part.where, dataset.get(), path);
    return dims.empty() ? 1 : dims[0];
}

// Rows of every dataset that belong to complete frames. A finished part holds nothing else;
// in a killed one the datasets may run past the last complete frame, and the rows that count
// follow the offsets (docs/reference/recording.md, "Frames complete").
void plan_rows(Part& part, const std::vector<Node>& tree) {
    for (const Node& node : tree) {
        if (!node.group) part.rows[node.path] = {0, length_of(part, node.path), 0};
    }
    if (part.complete) return;
    const hsize_t frames = part.frames;
    auto set_end = [&](const std::string& path, hsize_t end) {
        if (part.rows.count(path) != 0) part.rows[path].end = end;
    };
    auto target_of = [&](const std::string& offsets, const std::vector<std::string>& targets) {
        if (part.rows.count(offsets) == 0) return;
        const hsize_t entries = part.rows[offsets].end;
        const std::uint64_t end = entries == 0 ? 0 : read_u64(part, offsets, entries - 1);
        for (const std::string& target : targets) set_end(target, end);
    };
    std::set<std::string> known;
    for (const Node& node : tree) {
        if (node.group) continue;
        if (node.path.rfind(std::string(schema::k_frames) + "/", 0) == 0) {
            set_end(node.path, frames);
            known.insert(node.path);
        }
    }
    for (const char* offsets : {schema::k_pair_offsets, schema::k_gpu_pass_offsets, schema::k_gpu_survivor_offsets,
                                schema::k_depth_image_offsets}) {
        set_end(offsets, frames + 1);
    }
    target_of(schema::k_pair_offsets, {schema::k_pairs});
    target_of(schema::k_gpu_pass_offsets, {schema::k_gpu_passes});
    target_of(schema::k_gpu_survivor_offsets, {schema::k_gpu_survivors});
    target_of(schema::k_depth_image_offsets, {schema::k_depth_info, schema::k_depth_range});
    if (part.rows.count(schema::k_depth_info) != 0) set_end(schema::k_depth_pixel_offsets, part.rows[schema::k_depth_info].end + 1);
    target_of(schema::k_depth_pixel_offsets, {schema::k_depth_pixels});
    known.insert({schema::k_pair_offsets, schema::k_pairs, schema::k_gpu_pass_offsets, schema::k_gpu_passes,
                  schema::k_gpu_survivor_offsets, schema::k_gpu_survivors, schema::k_depth_image_offsets,
                  schema::k_depth_info, schema::k_depth_range, schema::k_depth_pixel_offsets, schema::k_depth_pixels});
    for (const Node& node : tree) {
        if (node.group || !is_topology_offsets(node.path)) continue;
        const std::string object = node.path.substr(0, node.path.rfind('/') + 1);
        // Topologies in force by the last complete frame.
        const std::string from = object + schema::k_topology_from_frame;
        const std::vector<std::uint32_t> starts = read_u32(part, from, 0, part.rows[from].end);
        const auto topologies = static_cast<hsize_t>(
            frames == 0 ? 0 : std::count_if(starts.begin(), starts.end(), [&](std::uint32_t s) { return s <= part.last; }));
        set_end(from, topologies);
        set_end(object + schema::k_topology_vertex_count, topologies);
        set_end(node.path, topologies + 1);
        target_of(node.path, {object + schema::k_triangles});
        set_end(object + schema::k_vertex_offsets, frames + 1);
        target_of(object + schema::k_vertex_offsets, {object + schema::k_positions});
        for (const char* name : {schema::k_topology_from_frame, schema::k_topology_vertex_count, schema::k_topology_offsets,
                                 schema::k_triangles, schema::k_vertex_offsets, schema::k_positions}) {
            known.insert(object + name);
        }
    }
    for (const Node& node : tree) {
        if (!node.group && known.count(node.path) == 0) {
            part.where.fail("incomplete part holds " + node.path +
                            ", which this collidescope cannot cut at its last complete frame");
        }
    }
}

// Part `part` (not the first) continues `previous`: offsets drop their leading entry, and the
// topology each object starts with is dropped where it equals the one `previous` ended with.
void plan_continuation(Part& part, const Part& previous, const std::vector<Node>& tree) {
    for (const Node& node : tree) {
        if (node.group || !is_offsets(node.path)) continue;
        Rows& rows = part.rows[node.path];
        if (rows.end > 0) rows.begin = 1;
    }
    for (const Node& node : tree) {
        if (node.group || !is_topology_offsets(node.path)) continue;
        const std::string object = node.path.substr(0, node.path.rfind('/') + 1);
        const std::string counts = object + schema::k_topology_vertex_count;
        const std::string triangles = object + schema::k_triangles;
        const hsize_t before = previous.rows.at(counts).end;
        if (before == 0 || part.rows.at(counts).end == 0) continue;
        const std::uint64_t prev_begin = read_u64(previous, node.path, before - 1);
        const std::uint64_t prev_end = read_u64(previous, node.path, before);
        const std::uint64_t own_end = read_u64(part, node.path, 1);
        if (read_u32(previous, counts, before - 1, 1) != read_u32(part, counts, 0, 1)) continue;
        if (prev_end - prev_begin != own_end) continue;
        if (read_u32(previous, triangles, prev_begin, prev_end - prev_begin) != read_u32(part, triangles, 0, own_end)) continue;
        part.rows[object + schema::k_topology_from_frame].begin = 1;
        part.rows[counts].begin = 1;
        part.rows[node.path].begin = 2;
        part.rows[node.path].base = own_end;
        part.rows[triangles].begin = own_end;
    }
}

std::string name_of(const Part& part) { return part.path.string(); }

// Same layout (groups, datasets, their types and widths) and attributes as the first part.
void check_compatible(const Part& first, const std::vector<Node>& tree, const Part& part) {
    std::vector<Node> other;
    walk(part.where, part.file.get(), "/", other);
    auto key = [](const std::vector<Node>& nodes) {
        std::set<std::string> keys;
        for (const Node& node : nodes) keys.insert(node.path + (node.group ? "/" : ""));
        return keys;
    };
    const std::set<std::string> a = key(tree), b = key(other);
    if (a != b) {
        std::string only;
        for (const std::string& path : a) if (b.count(path) == 0) { only = path + " only in " + name_of(first); break; }
        for (const std::string& path : b) if (only.empty() && a.count(path) == 0) { only = path + " only in " + name_of(part); break; }
        throw InputError(name_of(first) + " and " + name_of(part) + " have different layouts (" + only + ")");
    }
    std::vector<Node> objects = tree;
    objects.insert(objects.begin(), Node{"/", true});
    for (const Node& node : objects) {
        const h5::Id x = first.where.own(H5Oopen(first.file.get(), node.path.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + node.path);
        const h5::Id y = part.where.own(H5Oopen(part.file.get(), node.path.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + node.path);
        if (!node.group) {
            const h5::Id tx = first.where.own(H5Dget_type(x.get()), H5Tclose, "cannot read the type of " + node.path);
            const h5::Id ty = part.where.own(H5Dget_type(y.get()), H5Tclose, "cannot read the type of " + node.path);
            std::vector<hsize_t> dx = h5::shape(first.where, x.get(), node.path), dy = h5::shape(part.where, y.get(), node.path);
            if (!dx.empty()) dx[0] = 0;
            if (!dy.empty()) dy[0] = 0;
            if (H5Tequal(tx.get(), ty.get()) <= 0 || dx != dy) {
                throw InputError(name_of(first) + " and " + name_of(part) + " differ in the type or shape of " + node.path +
                                 " (made by different builds?)");
            }
        }
        const std::vector<join::Attribute> ax = join::read_attributes(first.where, x.get(), node.path);
        const std::vector<join::Attribute> ay = join::read_attributes(part.where, y.get(), node.path);
        for (const join::Attribute& attribute : ax) {
            if (node.path == "/" && k_per_run.count(attribute.name) != 0) continue;
            const auto match = std::find_if(ay.begin(), ay.end(), [&](const join::Attribute& o) { return o.name == attribute.name; });
            if (match == ay.end() || !join::same_value(attribute, *match)) {
                throw InputError(name_of(first) + " and " + name_of(part) + " differ in attribute " + attribute.name + " of " +
                                 node.path + " (not parts of one session)");
            }
        }
        for (const join::Attribute& attribute : ay) {
            if (node.path == "/" && k_per_run.count(attribute.name) != 0) continue;
            if (std::none_of(ax.begin(), ax.end(), [&](const join::Attribute& o) { return o.name == attribute.name; })) {
                throw InputError(name_of(first) + " and " + name_of(part) + " differ in attribute " + attribute.name + " of " +
                                 node.path + " (not parts of one session)");
            }
        }
    }
}

Part open_part(const std::filesystem::path& path, bool allow_incomplete) {
    Part part;
    part.path = path;
    part.where = h5::Where(path.string());
    {
        const Recording recording(path);  // schema name and version, frames complete
        part.frames = recording.frames_complete();
        part.complete = recording.finished() && recording.interrupted().empty() &&
                        recording.frames_complete() == recording.frames_requested();
        if (!part.complete && !allow_incomplete) {
            part.where.fail("incomplete part (" + recording.partial_reason() + "); join it with --allow-incomplete");
        }
        if (recording.has_regions()) {
            // Region ids run on from frame to frame within one process: parts cannot be joined.
            part.where.fail("holds /regions (record --regions), whose ids follow regions across frames; join does not "
                            "merge them: record regions in one process");
        }
        if (recording.has_intervals()) {
            // A part's first row ends no interval: the one between two parts was never detected.
            part.where.fail("holds /intervals (record --between-frames); each part lacks the interval into its first frame, "
                            "so join does not merge them: record between frames in one process");
        }
        const std::vector<std::uint32_t> frames = recording.frame_indices();
        if (!frames.empty()) {
            part.first = frames.front();
            part.last = frames.back();
        }
    }
    part.file = open_part_file(part.where);
    // A virtual join's mappings name files relative to it, and its rows cannot be copied raw.
    if (!virtual_sources::list(part.where, part.file.get()).empty()) {
        part.where.fail("is a virtual join (its datasets map rows of other files), not a part: join the parts it maps instead");
    }
    part.frame_begin = h5::read_int_attr(part.where, part.file.get(), "frame_begin").value_or(0);
    part.frame_end = h5::read_int_attr(part.where, part.file.get(), "frame_end").value_or(0);
    return part;
}

// Sorted by first frame; ranges must meet exactly (a gap only after an incomplete part).
void check_ranges(const std::vector<Part>& parts) {
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const Part& a = parts[i - 1];
        const Part& b = parts[i];
        const std::string names = name_of(a) + " and " + name_of(b);
        if (b.first <= a.last) {
            throw InputError(names + " overlap: both hold frame " + std::to_string(b.first));
        }
        if (a.complete && b.first != a.frame_end) {
            throw InputError(names + " leave a gap: frames " + std::to_string(a.frame_end) + ".." +
                             std::to_string(b.first - 1) + " are in neither");
        }
        if (a.frame_begin >= b.frame_begin || (a.frame_end > b.frame_begin)) {
            throw InputError(names + " overlap: frames " + std::to_string(a.frame_begin) + ":" + std::to_string(a.frame_end) +
                             " and " + std::to_string(b.frame_begin) + ":" + std::to_string(b.frame_end) + " were asked for");
        }
    }
}

// The datasets a virtual join maps instead of copying: extensible ones (fixed-size ones are
// the first part's), not offsets (their values are rebased), with at least
// options.virtual_min_rows rows per part on average.
std::set<std::string> plan_virtual(const std::vector<Part>& parts, const std::vector<Node>& tree, const JoinOptions& options) {
    std::set<std::string> mapped;
    if (options.layout != JoinLayout::Virtual) return mapped;
    for (const Node& node : tree) {
        if (node.group || is_offsets(node.path)) continue;
        hsize_t total = 0;
        for (const Part& part : parts) {
            const Rows rows = part.rows.at(node.path);
            if (rows.end > rows.begin) total += rows.end - rows.begin;
        }
        if (total == 0 || total < options.virtual_min_rows * parts.size()) continue;
        const Part& first = parts.front();
        const h5::Id dataset = h5::open_dataset(first.where, first.file.get(), node.path);
        const h5::Id space = first.where.own(H5Dget_space(dataset.get()), H5Sclose, "cannot read the shape of " + node.path);
        hsize_t dims[2] = {}, max_dims[2] = {};
        const int rank = H5Sget_simple_extent_ndims(space.get());
        if (rank < 1 || rank > 2) continue;
        H5Sget_simple_extent_dims(space.get(), dims, max_dims);
        if (max_dims[0] == H5S_UNLIMITED) mapped.insert(node.path);
    }
    return mapped;
}

h5::Id create_mapped(const std::vector<Part>& parts, const std::string& path, const h5::Where& where, hid_t out) {
    const Part& first = parts.front();
    const h5::Id source = h5::open_dataset(first.where, first.file.get(), path);
    const h5::Id type = first.where.own(H5Dget_type(source.get()), H5Tclose, "cannot read the type of " + path);
    const std::vector<hsize_t> dims = h5::shape(first.where, source.get(), path);
    std::vector<join::VirtualPiece> pieces;
    for (const Part& part : parts) {
        const Rows rows = part.rows.at(path);
        if (rows.end <= rows.begin) continue;
        pieces.push_back({join::source_name(part.path, where.file()), rows.begin, rows.end, length_of(part, path)});
    }
    return join::create_virtual(where, out, path, type.get(), static_cast<int>(dims.size()), dims.size() == 2 ? dims[1] : 1,
                                pieces);
}

void create_tree(const std::vector<Part>& parts, const std::vector<Node>& tree, const std::set<std::string>& mapped,
                 const h5::Where& where, hid_t out) {
    const Part& first = parts.front();
    for (const Node& node : tree) {
        const h5::Id source = first.where.own(H5Oopen(first.file.get(), node.path.c_str(), H5P_DEFAULT), H5Oclose,
                                              "cannot open " + node.path);
        h5::Id target;
        if (node.group) {
            target = h5::create_group(where, out, node.path);
        } else if (mapped.count(node.path) != 0) {
            target = create_mapped(parts, node.path, where, out);
        } else {
            const h5::Id type = first.where.own(H5Dget_type(source.get()), H5Tclose, "cannot read the type of " + node.path);
            const h5::Id dcpl = first.where.own(H5Dget_create_plist(source.get()), H5Pclose, "cannot read the layout of " + node.path);
            const h5::Id space = first.where.own(H5Dget_space(source.get()), H5Sclose, "cannot read the shape of " + node.path);
            const int rank = H5Sget_simple_extent_ndims(space.get());
            std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0))), max_dims(dims.size());
            if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), max_dims.data());
            if (rank < 1 || max_dims[0] != H5S_UNLIMITED) {
                // Fixed-size datasets are not per-frame: the first part's copy stands (the
                // parts' attributes were checked equal; their values are the session's).
                where.check(H5Ocopy(first.file.get(), node.path.c_str(), out, node.path.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                            "cannot copy " + node.path);
                continue;
            }
            dims[0] = 0;
            const h5::Id out_space = where.own(H5Screate_simple(rank, dims.data(), max_dims.data()), H5Sclose,
                                               "cannot make a dataspace");
            // A chunk cache that holds a positions chunk while a part boundary fills it.
            const h5::Id dapl = where.own(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose, "cannot create a property list");
            where.check(H5Pset_chunk_cache(dapl.get(), 521, std::size_t{64} << 20, 1.0), "cannot set the chunk cache");
            target = where.own(H5Dcreate2(out, node.path.c_str(), type.get(), out_space.get(), H5P_DEFAULT, dcpl.get(), dapl.get()),
                               H5Dclose, "cannot create dataset " + node.path);
        }
        for (const join::Attribute& attribute : join::read_attributes(first.where, source.get(), node.path)) {
            join::write_attribute(where, target.get(), attribute);
        }
    }
}

void copy_offsets(const std::vector<Part>& parts, const std::string& path, const h5::Where& where, hid_t target) {
    hsize_t at = 0;
    std::uint64_t running = 0;
    for (const Part& part : parts) {
        const Rows rows = part.rows.at(path);
        if (rows.end <= rows.begin) continue;
        const h5::Id source = h5::open_dataset(part.where, part.file.get(), path);
        std::vector<std::uint64_t> values(rows.end - rows.begin);
        h5::read_rows(part.where, source.get(), path, H5T_NATIVE_UINT64, rows.begin, values.size(), values.data());
        for (std::uint64_t& value : values) value = value - rows.base + running;
        h5::extend(where, target, path, at + values.size());
        h5::write_rows(where, target, path, at, H5T_NATIVE_UINT64, values.size(), values.data());
        at += values.size();
        running = values.back();
    }
}

// The first part's root attributes but those written when the output is finished; the
// frame range ends where the last part's does.
void write_root_attributes(const std::vector<Part>& parts, const h5::Where& where, hid_t out) {
    const Part& first = parts.front();
    for (const join::Attribute& attribute : join::read_attributes(first.where, first.file.get(), "/")) {
        if (k_written_at_finish.count(attribute.name) != 0) continue;
        if (attribute.name == "frame_end") {
            h5::write_attr(where, out, "frame_end", parts.back().frame_end);
            continue;
        }
        join::write_attribute(where, out, attribute);
    }
}

JoinSummary write_joined(std::vector<Part>& parts, const std::vector<Node>& tree, const h5::Where& where, bool complete,
                         const JoinOptions& options) {
    const h5::Id fapl = where.own(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a property list");
    where.check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST), "cannot select the latest file format");
    const h5::Id fcpl = where.own(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "cannot create a property list");
    h5::keep_compact(where, fcpl.get(), "/");
    h5::Id out = where.own(H5Fcreate(where.file().c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), H5Fclose,
                           "cannot create the joined recording (is the directory writable?)");
    write_root_attributes(parts, where, out.get());
    const std::set<std::string> mapped = plan_virtual(parts, tree, options);
    create_tree(parts, tree, mapped, where, out.get());
    JoinSummary summary;
    summary.parts = parts.size();
    for (const Part& part : parts) summary.frames += part.frames;
    summary.complete = complete;
    for (const Node& node : tree) {
        if (node.group || parts.front().rows.count(node.path) == 0) continue;
        if (mapped.count(node.path) != 0) {
            ++summary.virtual_datasets;
            for (const Part& part : parts) {
                const Rows rows = part.rows.at(node.path);
                if (rows.end > rows.begin) summary.virtual_rows += rows.end - rows.begin;
            }
            continue;
        }
        const h5::Id target = h5::open_dataset(where, out.get(), node.path);
        {
            const h5::Id space = where.own(H5Dget_space(target.get()), H5Sclose, "cannot read the shape of " + node.path);
            hsize_t dims[8] = {}, max_dims[8] = {};
            if (H5Sget_simple_extent_dims(space.get(), dims, max_dims) < 1 || max_dims[0] != H5S_UNLIMITED) continue;  // copied whole
        }
        if (is_offsets(node.path)) {
            copy_offsets(parts, node.path, where, target.get());
            continue;
        }
        join::RowAppender appender(where, target.get(), node.path);
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const Part& part = parts[i];
            const Rows rows = part.rows.at(node.path);
            if (rows.end <= rows.begin) continue;
            const h5::Id source = h5::open_dataset(part.where, part.file.get(), node.path);
            appender.append(part.where, source.get(), rows.begin, rows.end - rows.begin, i + 1 == parts.size());
        }
        appender.finish();
        summary.raw_chunks += appender.count().raw_chunks;
        summary.raw_bytes += appender.count().raw_bytes;
        summary.rewritten_rows += appender.count().rewritten_rows;
    }
    if (complete) {
        h5::write_attr(where, out.get(), schema::k_attr_frames_recorded, static_cast<std::int64_t>(summary.frames));
        std::int64_t stride = 1;
        for (const Part& part : parts) {
            stride = std::max(stride, h5::read_int_attr(part.where, part.file.get(), schema::k_attr_positions_stride).value_or(1));
        }
        h5::write_attr(where, out.get(), schema::k_attr_positions_stride, stride);
        h5::write_attr(where, out.get(), schema::k_attr_finished, std::int64_t{1});
    }
    if (!out.reset()) where.fail("cannot close the joined recording (disk full?)");
    return summary;
}

}  // namespace

JoinSummary join_recordings(const std::vector<std::filesystem::path>& paths, const std::filesystem::path& output,
                            const JoinOptions& options) {
    h5::silence();
    if (paths.empty()) throw InputError("join: no parts given");
    std::error_code error;
    for (const std::filesystem::path& path : paths) {
        if (std::filesystem::equivalent(path, output, error)) {
            throw InputError(output.string() + ": the output is one of the parts");
        }
    }
    std::vector<Part> parts;
    for (const std::filesystem::path& path : paths) {
        Part part = open_part(path, options.allow_incomplete);
        if (part.frames == 0) continue;  // a part killed before its first frame adds nothing
        parts.push_back(std::move(part));
    }
    if (parts.empty()) throw InputError(paths.front().string() + ": no complete frame in any part");
    std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.first < b.first; });
    check_ranges(parts);
    std::vector<Node> tree;
    walk(parts.front().where, parts.front().file.get(), "/", tree);
    for (std::size_t i = 1; i < parts.size(); ++i) check_compatible(parts.front(), tree, parts[i]);
    bool complete = true;
    for (Part& part : parts) {
        plan_rows(part, tree);
        complete = complete && part.complete;
    }
    for (std::size_t i = 1; i < parts.size(); ++i) plan_continuation(parts[i], parts[i - 1], tree);

    const std::filesystem::path partial = output.string() + ".partial";
    try {
        JoinSummary summary = write_joined(parts, tree, h5::Where(partial.string()), complete, options);
        std::filesystem::rename(partial, output);
        return summary;
    } catch (...) {
        std::filesystem::remove(partial, error);
        throw;
    }
}

}  // namespace collidescope::recorder
