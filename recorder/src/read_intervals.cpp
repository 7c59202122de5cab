// Reading /intervals (schema 1.7, record --between-frames): an interval's stats row, then its
// contacts through the offsets, each checked against the rows they point into.

#include "read_blocks.hpp"
#include "recording_state.hpp"

#include "collidescope/recorder/reader.hpp"

#include <cmath>

namespace collidescope::recorder {

bool Recording::has_intervals() const { return h5::exists(m_impl->file.get(), schema::k_interval_offsets); }

namespace {

IntervalStats stats_of(const std::uint64_t* counts, const double* ms, double tolerance) {
    IntervalStats s;
    s.candidate_pairs = counts[0], s.start_contacts = counts[1], s.primitive_queries = counts[2];
    s.inclusion_boxes = counts[3], s.contacts = counts[4], s.pass_throughs = counts[5], s.unresolved = counts[6];
    s.broad_ms = ms[0], s.narrow_ms = ms[1], s.ms = ms[2];
    s.tolerance = tolerance;
    return s;
}

}  // namespace

std::vector<IntervalStats> Recording::interval_stats() const {
    const RecordingState& impl = *m_impl;
    if (!has_intervals()) return {};
    const auto counts = read_block<std::uint64_t>(impl, schema::k_interval_counts, H5T_NATIVE_UINT64, 0, impl.frames, 7);
    const auto ms = read_block<double>(impl, schema::k_interval_ms, H5T_NATIVE_DOUBLE, 0, impl.frames, 3);
    const auto tolerance = read_block<double>(impl, schema::k_interval_tolerance, H5T_NATIVE_DOUBLE, 0, impl.frames, 1);
    std::vector<IntervalStats> out;
    for (std::uint64_t r = 0; r < impl.frames; ++r) out.push_back(stats_of(&counts[7 * r], &ms[3 * r], tolerance[r]));
    return out;
}

RecordedInterval Recording::interval(std::uint64_t row, bool with_contacts) const {
    const RecordingState& impl = *m_impl;
    impl.check_row(row);
    if (!has_intervals()) impl.where.fail("no /intervals in this recording (record it with --between-frames)");
    if (row == 0) impl.where.fail("frame row 0 ends no interval (the first interval ends at row 1)");
    RecordedInterval out;
    out.row = row;
    const auto index = read_block<std::uint32_t>(impl, schema::k_frame_index, H5T_NATIVE_UINT32, row - 1, 2, 1);
    out.from_frame = index[0], out.to_frame = index[1];
    const auto counts = read_block<std::uint64_t>(impl, schema::k_interval_counts, H5T_NATIVE_UINT64, row, 1, 7);
    const auto ms = read_block<double>(impl, schema::k_interval_ms, H5T_NATIVE_DOUBLE, row, 1, 3);
    const auto tolerance = read_block<double>(impl, schema::k_interval_tolerance, H5T_NATIVE_DOUBLE, row, 1, 1);
    out.stats = stats_of(counts.data(), ms.data(), tolerance[0]);
    if (!with_contacts) return out;
    const auto offsets = read_offsets(impl, schema::k_interval_offsets, row, 1, schema::k_interval_pairs);
    const std::uint64_t first = offsets[0], count = offsets[1] - offsets[0];
    for (const char* path : {schema::k_interval_toi, schema::k_interval_flags}) {
        if (impl.rows(path) < offsets[1]) {
            impl.where.fail(std::string(path) + ": shorter than " + schema::k_interval_pairs + " (corrupt recording)");
        }
    }
    const auto pairs = read_block<std::uint32_t>(impl, schema::k_interval_pairs, H5T_NATIVE_UINT32, first, count, 4);
    const auto toi = read_block<double>(impl, schema::k_interval_toi, H5T_NATIVE_DOUBLE, first, count, 1);
    const auto flags = read_block<std::uint8_t>(impl, schema::k_interval_flags, H5T_NATIVE_UINT8, first, count, 1);
    out.contacts.resize(count);
    for (std::uint64_t k = 0; k < count; ++k) {
        IntervalContact& c = out.contacts[k];
        c.pair = {pairs[4 * k], pairs[4 * k + 1], pairs[4 * k + 2], pairs[4 * k + 3]};
        c.toi = toi[k];
        if (!(c.toi >= 0 && c.toi <= 1)) {
            impl.where.fail(std::string(schema::k_interval_toi) + ": row " + std::to_string(first + k) + " (" +
                            std::to_string(c.toi) + ") is not a time in [0, 1] (corrupt recording)");
        }
        c.pass_through = (flags[k] & schema::k_flag_pass_through) != 0;
        c.resolved = (flags[k] & schema::k_flag_unresolved) == 0;
    }
    return out;
}

}  // namespace collidescope::recorder
