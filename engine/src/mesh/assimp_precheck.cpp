// check_counts_fit: header counts against the file's size, before assimp allocates them; and
// QuietCerr.
//
// OFF ([ST][C][N][4][n]OFF or no keyword at all, then the vertex, face and edge counts): assimp's
// importer allocates the vertices and faces the header declares (as 32-bit counts, wrapping
// larger ones) before reading them, then reads one line per vertex and per face. A line holds
// at least one character and its line end, so a file with V vertices and F faces holds at
// least 2 (V + F) - 1 bytes after the counts. The bound is loose on purpose (a vertex line
// holds three numbers), so that no file assimp reads is refused here; a header that lies by
// more than that bound (invalid/OutOfMemory.off declares 353535235358 vertices in
// 309 bytes) is.

#include "mesh/assimp_checks.hpp"
#include "mesh/format_extension.hpp"

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

namespace collidescope {
namespace {

// Tokens of an OFF header: whitespace-separated, '#' comments to the end of the line.
class Tokens {
public:
    explicit Tokens(std::string_view text) : m_text(text) {}

    std::string_view next() {
        skip_blanks();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !std::isspace(static_cast<unsigned char>(m_text[m_pos])) &&
               m_text[m_pos] != '#') {
            ++m_pos;
        }
        return m_text.substr(start, m_pos - start);
    }
    std::size_t position() const { return m_pos; }

private:
    void skip_blanks() {
        while (m_pos < m_text.size()) {
            if (m_text[m_pos] == '#') {
                while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
            } else if (std::isspace(static_cast<unsigned char>(m_text[m_pos]))) {
                ++m_pos;
            } else {
                break;
            }
        }
    }

    std::string_view m_text;
    std::size_t m_pos = 0;
};

// A count of decimal digits only (capped at 2^63, far above any file size); nothing otherwise.
std::optional<std::uint64_t> count(std::string_view token) {
    if (token.empty()) return std::nullopt;
    std::uint64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') return std::nullopt;
        value = std::min<std::uint64_t>(value * 10 + static_cast<std::uint64_t>(c - '0'), std::uint64_t{1} << 63);
    }
    return value;
}

bool is_off_keyword(std::string_view token) {
    return token.size() >= 3 && token.size() <= 9 && token.substr(token.size() - 3) == "OFF";
}

// Headers this check does not understand are left to assimp, which refuses them itself.
void check_off(const std::filesystem::path& file) {
    const std::vector<std::byte> bytes = read_file_bytes(file);
    Tokens tokens({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    std::string_view token = tokens.next();
    if (is_off_keyword(token)) {
        if (token.find('n') != std::string_view::npos && !count(tokens.next())) return;  // nOFF: dimension
        token = tokens.next();
    }
    const std::optional<std::uint64_t> vertices = count(token);
    const std::optional<std::uint64_t> faces = count(tokens.next());
    if (!vertices || !faces) return;
    const std::uint64_t left = bytes.size() - tokens.position();
    // In long double: V and F are below 2^63, so 2 (V + F) cannot overflow it.
    const long double needed = 2.0L * (static_cast<long double>(*vertices) + static_cast<long double>(*faces)) - 1;
    if (needed <= static_cast<long double>(left)) return;
    throw InputError(file.string() + ": header: " + std::to_string(*vertices) + " vertices and " +
                     std::to_string(*faces) + " faces cannot fit in the " + std::to_string(left) +
                     " bytes after the counts (each takes a line of at least 2 bytes)");
}

std::mutex g_cerr_mutex;
int g_cerr_guards = 0;
std::streambuf* g_cerr_buffer = nullptr;

}  // namespace

void check_counts_fit(const std::filesystem::path& file) {
    if (format_extension(file) == ".off") check_off(file);
}

QuietCerr::QuietCerr() {
    const std::lock_guard lock(g_cerr_mutex);
    if (g_cerr_guards++ == 0) g_cerr_buffer = std::cerr.rdbuf(nullptr);
}

QuietCerr::~QuietCerr() {
    const std::lock_guard lock(g_cerr_mutex);
    if (--g_cerr_guards == 0) {
        std::cerr.rdbuf(g_cerr_buffer);
        std::cerr.clear();
    }
}

}  // namespace collidescope
