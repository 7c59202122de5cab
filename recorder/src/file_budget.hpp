#pragma once
// --budget: which frames keep their depth images and vertex positions, so that the file ends
// near the budget. Depth images go first, then positions (issue 6).

#include <cstdint>

namespace collidescope::recorder {

/// Keeps the depth images of every `depth_stride()`th frame that has some, and the positions
/// of every `positions_stride()`th recorded frame (strides are powers of 2, never lowered; 0:
/// none any more). From the file's growth since the first frames (which allocate every
/// dataset's first chunk) it estimates what each further frame costs without either, what a
/// kept depth frame and a kept positions frame add, and raises the depth stride until the
/// remaining frames fit into the budget; only with no depth images left does it raise the
/// positions stride the same way.
class FileBudget {
public:
    /// `budget` bytes (0: no bound) over `frames_total` recorded frames.
    FileBudget(std::uint64_t budget, std::uint64_t frames_total) : m_budget(budget), m_total(frames_total) {}

    /// Whether the next frame with depth images keeps them (call once per such frame).
    bool keep_depth();
    /// Whether recorded frame `row` keeps its positions.
    bool keep_positions(std::uint64_t row) const { return m_positions.stride != 0 && row % m_positions.stride == 0; }

    /// What the file holds after a frame was written.
    struct Usage {
        std::uint64_t rows = 0;             ///< frames written
        std::uint64_t file_bytes = 0;
        std::uint64_t positions_bytes = 0;  ///< storage of every positions dataset
        std::uint64_t positions_kept = 0;   ///< frames whose positions were written
        std::uint64_t depth_bytes = 0;      ///< storage of the depth pixels
        std::uint64_t depth_kept = 0;       ///< frames whose depth images were written
        std::uint64_t depth_seen = 0;       ///< frames that had depth images
    };
    void update(const Usage& usage);

    std::uint32_t depth_stride() const { return m_depth.stride; }
    std::uint32_t positions_stride() const { return m_positions.stride; }

private:
    static constexpr std::uint64_t k_warmup = 2;  ///< frames whose growth includes first chunks
    struct Stride {
        std::uint32_t stride = 1;
        /// Doubles the stride while `need(stride)` exceeds `room`; 0 once not even one more
        /// frame (`frames` remaining) fits.
        template <class Need>
        void raise(double frames, double room, Need need);
    };
    std::uint64_t m_budget;
    std::uint64_t m_total;
    Stride m_depth;
    Stride m_positions;
    std::uint64_t m_depth_frames = 0;  ///< frames with depth images seen by keep_depth
    Usage m_base;
};

}  // namespace collidescope::recorder
