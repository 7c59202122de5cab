// PNG encoding: stb_image_write's PNG filters, zlib's deflate (faster than stb's own, and the
// output depends only on the pixels and the level).

#include "png.hpp"

#include "collidescope/error.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace {

// Deflate level: 1 is zlib's fastest; the replay's images are large flat areas, where level 1
// already compresses well, and a 1280x720 frame encodes several times faster than at 6.
constexpr int k_zlib_level = 1;

unsigned char* zlib_compress(unsigned char* data, int length, int* out_length, int /*quality*/) {
    uLongf size = compressBound(uLong(length));
    auto* out = static_cast<unsigned char*>(std::malloc(size));
    if (out == nullptr) return nullptr;
    if (compress2(out, &size, data, uLong(length), k_zlib_level) != Z_OK) {
        std::free(out);
        return nullptr;
    }
    *out_length = int(size);
    return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace {

// One filter for every row, "sub" (1): stb's own choice tries all five filters per row (Paeth
// included), which cost more than the deflate itself on 1280x720 frames; the replay's images
// are mostly flat runs along rows, where "sub" does as well. Set once, before any thread runs.
[[maybe_unused]] const int k_png_filter = (stbi_write_force_png_filter = 1);

}  // namespace

namespace collidescope::replays {

void write_png(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgba, int width, int height) {
    int length = 0;
    unsigned char* png = stbi_write_png_to_mem(rgba.data(), width * 4, width, height, 4, &length);
    if (png == nullptr) throw InputError(file.string() + ": cannot encode the PNG");
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(png), length);
    std::free(png);
    out.close();
    if (!out) throw InputError(file.string() + ": cannot write the PNG");
}

std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& rgba, int width, int x, int y, int w, int h) {
    std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h) * 4);
    for (int row = 0; row < h; ++row) {
        std::copy_n(&rgba[(std::size_t(y + row) * std::size_t(width) + std::size_t(x)) * 4], std::size_t(w) * 4,
                    &out[std::size_t(row) * std::size_t(w) * 4]);
    }
    return out;
}

std::vector<std::uint8_t> downscale(const std::vector<std::uint8_t>& rgba, int from_width, int from_height, int width,
                                    int height) {
    std::vector<std::uint8_t> out(std::size_t(width) * std::size_t(height) * 4);
    for (int y = 0; y < height; ++y) {
        const int y0 = y * from_height / height;
        const int y1 = std::max(y0 + 1, (y + 1) * from_height / height);
        for (int x = 0; x < width; ++x) {
            const int x0 = x * from_width / width;
            const int x1 = std::max(x0 + 1, (x + 1) * from_width / width);
            unsigned sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy) {
                for (int sx = x0; sx < x1; ++sx) {
                    const std::uint8_t* p = &rgba[(std::size_t(sy) * std::size_t(from_width) + std::size_t(sx)) * 4];
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                }
            }
            const unsigned count = unsigned((y1 - y0) * (x1 - x0));
            for (int c = 0; c < 4; ++c) {
                out[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + std::size_t(c)] =
                    std::uint8_t((sum[c] + count / 2) / count);
            }
        }
    }
    return out;
}

}  // namespace collidescope::replays
