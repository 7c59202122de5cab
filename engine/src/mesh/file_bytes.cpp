// read_file_bytes: whole files into memory, gunzipped in memory (zlib) when they end in .gz.

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace collidescope {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
    throw InputError(file.string() + ": " + what);
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

std::vector<std::byte> read_plain(const std::filesystem::path& file) {
    std::error_code error;
    const auto status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status)) fail(file, "no such file");
    if (std::filesystem::is_directory(status)) fail(file, "is a directory, not a file");
    const std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(file.c_str(), "rb"));
    if (!stream) fail(file, std::string("cannot open (") + std::strerror(errno) + ")");
    std::vector<std::byte> bytes(std::filesystem::file_size(file, error));
    if (error) bytes.clear();
    std::size_t size = std::fread(bytes.data(), 1, bytes.size(), stream.get());
    // Read on past the expected size, in case the file grew (or has no size, like a pipe).
    std::byte chunk[65536];
    while (std::size_t n = std::fread(chunk, 1, sizeof chunk, stream.get())) {
        bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(size), chunk, chunk + n);
        size += n;
    }
    if (std::ferror(stream.get())) fail(file, std::string("read error (") + std::strerror(errno) + ")");
    bytes.resize(size);
    return bytes;
}

bool is_gzip_member(const std::byte* at, std::size_t left) {
    return left >= 2 && at[0] == std::byte{0x1f} && at[1] == std::byte{0x8b};
}

struct InflateEnd {
    void operator()(z_stream* stream) const { inflateEnd(stream); }
};

// Inflates every gzip member in `in` (gzip allows concatenated members; trailing non-gzip
// bytes are ignored, as gzip(1) does).
std::vector<std::byte> gunzip(const std::vector<std::byte>& in, const std::filesystem::path& file) {
    if (!is_gzip_member(in.data(), in.size())) fail(file, "not gzip data");
    z_stream stream{};
    if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) fail(file, "cannot start zlib");
    const std::unique_ptr<z_stream, InflateEnd> guard(&stream);
    std::vector<std::byte> out(std::max<std::size_t>(in.size() * 4, 1 << 16));
    std::size_t in_pos = 0;
    std::size_t out_pos = 0;
    constexpr std::size_t k_chunk = std::size_t{1} << 30;  // zlib counts in 32-bit uInt
    while (true) {
        if (out_pos == out.size()) out.resize(out.size() * 2);
        const std::size_t in_chunk = std::min(in.size() - in_pos, k_chunk);
        const std::size_t out_chunk = std::min(out.size() - out_pos, k_chunk);
        stream.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in.data() + in_pos));
        stream.avail_in = static_cast<uInt>(in_chunk);
        stream.next_out = reinterpret_cast<Bytef*>(out.data() + out_pos);
        stream.avail_out = static_cast<uInt>(out_chunk);
        const int result = inflate(&stream, Z_NO_FLUSH);
        in_pos += in_chunk - stream.avail_in;
        out_pos += out_chunk - stream.avail_out;
        if (result == Z_STREAM_END) {
            if (!is_gzip_member(in.data() + in_pos, in.size() - in_pos)) break;
            inflateReset(&stream);
        } else if (result == Z_BUF_ERROR || result == Z_OK) {
            if (in_pos == in.size() && stream.avail_out != 0) fail(file, "gzip data truncated");
        } else {
            fail(file, std::string("corrupt gzip data (") + (stream.msg ? stream.msg : "zlib error") + ")");
        }
    }
    out.resize(out_pos);
    return out;
}

}  // namespace

std::vector<std::byte> read_file_bytes(const std::filesystem::path& file) {
    std::vector<std::byte> bytes = read_plain(file);
    if (file.extension() == ".gz") return gunzip(bytes, file);
    return bytes;
}

}  // namespace collidescope
