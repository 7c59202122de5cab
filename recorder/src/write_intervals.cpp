// /intervals (schema 1.7): each frame with the one before it, written only by `record
// --between-frames` (docs/explanation/between-frames.md). Row r holds the interval from recorded
// frame r - 1 to frame r; row 0 holds none. Contact rows first, offsets after them, so an
// offset never points past its rows.

#include "recording_writer.hpp"

#include "collidescope/recorder/schema.hpp"

namespace collidescope::recorder {
namespace {

constexpr hsize_t k_interval_chunk = 256;  // intervals per chunk (as /frames)
constexpr hsize_t k_contact_chunk = 8192;  // pairs per chunk (as /collisions/pairs)
constexpr const char* k_unit_toi = "1 (a fraction of the interval: 0 the first frame, 1 the second)";

}  // namespace

void RecordingWriter::create_intervals() {
    h5::create_group(m_where, m_file.get(), schema::k_intervals);
    IntervalColumns& c = m_intervals;
    c.offsets = make_column(schema::k_interval_offsets, {H5T_STD_U64LE, 1, k_interval_chunk, 0, schema::k_unit_none});
    const std::uint64_t zero = 0;
    append_value(c.offsets, H5T_NATIVE_UINT64, &zero);
    c.counts = make_column(schema::k_interval_counts, {H5T_STD_U64LE, 7, k_interval_chunk, 0, schema::k_unit_none});
    c.ms = make_column(schema::k_interval_ms, {H5T_IEEE_F64LE, 3, k_interval_chunk, 0, schema::k_unit_ms});
    c.tolerance = make_column(schema::k_interval_tolerance, {H5T_IEEE_F64LE, 1, k_interval_chunk, 0, schema::k_unit_length});
    c.pairs = make_column(schema::k_interval_pairs, {H5T_STD_U32LE, 4, k_contact_chunk, m_deflate, schema::k_unit_none});
    c.toi = make_column(schema::k_interval_toi, {H5T_IEEE_F64LE, 1, k_contact_chunk, m_deflate, k_unit_toi});
    c.flags = make_column(schema::k_interval_flags, {H5T_STD_U8LE, 1, k_contact_chunk, m_deflate, schema::k_unit_none});
    c.present = true;
}

void RecordingWriter::append_intervals(std::span<const FrameRecord> records) {
    IntervalColumns& c = m_intervals;
    std::vector<TrianglePair> pairs;
    std::vector<double> toi, ms, tolerance;
    std::vector<std::uint8_t> flags;
    std::vector<std::uint64_t> counts, ends;
    std::uint64_t end = c.pairs.length;
    for (const FrameRecord& record : records) {
        const IntervalRecord& i = record.interval;
        pairs.insert(pairs.end(), i.pairs.begin(), i.pairs.end());
        toi.insert(toi.end(), i.toi.begin(), i.toi.end());
        flags.insert(flags.end(), i.flags.begin(), i.flags.end());
        counts.insert(counts.end(), std::begin(i.counts), std::end(i.counts));
        ms.insert(ms.end(), std::begin(i.ms), std::end(i.ms));
        tolerance.push_back(i.tolerance);
        ends.push_back(end += i.pairs.size());
    }
    const auto rows = [&](Column& column, hid_t type, std::size_t count, const void* data) {
        h5::append_rows(m_where, column.dataset.get(), column.path, column.length, type, count, data);
    };
    rows(c.pairs, H5T_NATIVE_UINT32, pairs.size(), pairs.data());
    rows(c.toi, H5T_NATIVE_DOUBLE, toi.size(), toi.data());
    rows(c.flags, H5T_NATIVE_UINT8, flags.size(), flags.data());
    rows(c.counts, H5T_NATIVE_UINT64, records.size(), counts.data());
    rows(c.ms, H5T_NATIVE_DOUBLE, records.size(), ms.data());
    rows(c.tolerance, H5T_NATIVE_DOUBLE, records.size(), tolerance.data());
    rows(c.offsets, H5T_NATIVE_UINT64, ends.size(), ends.data());
}

}  // namespace collidescope::recorder
