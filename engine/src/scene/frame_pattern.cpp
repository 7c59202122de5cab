// Frame patterns: parsing, matching and expansion to the existing consecutive frame files.

#include "scene/frame_pattern.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <set>

namespace collidescope {
namespace {

struct Field {
    std::size_t start = 0;
    std::size_t length = 0;
    int width = 0;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The first `%d`, `%0Nd` or `#...#` field at or after `from`.
std::optional<Field> find_field(const std::string& name, std::size_t from) {
    for (std::size_t i = from; i < name.size(); ++i) {
        if (name[i] == '#') {
            std::size_t end = i;
            while (end < name.size() && name[end] == '#') ++end;
            return Field{i, end - i, static_cast<int>(end - i)};
        }
        if (name[i] != '%') continue;
        std::size_t end = i + 1;
        const bool zero = end < name.size() && name[end] == '0';
        if (zero) ++end;
        int width = 0;
        while (end < name.size() && is_digit(name[end]) && width < 100) width = width * 10 + (name[end++] - '0');
        // `%Nd` without the zero would pad with spaces: not a file-name pattern.
        const bool valid = end < name.size() && name[end] == 'd' && (zero || width == 0);
        if (valid) return Field{i, end + 1 - i, width};
    }
    return std::nullopt;
}

// "cloth..ply.gz" -> "cloth.": drops .gz, then the format's extension.
std::string strip_extensions(std::string name) {
    if (name.ends_with(".gz")) name.resize(name.size() - 3);
    const std::size_t dot = name.rfind('.');
    if (dot != std::string::npos) name.resize(dot);
    return name;
}

}  // namespace

std::string FramePattern::file_name(std::uint64_t number) const {
    std::string digits = std::to_string(number);
    if (digits.size() < static_cast<std::size_t>(width)) {
        digits.insert(0, static_cast<std::size_t>(width) - digits.size(), '0');
    }
    return prefix + digits + suffix;
}

std::optional<std::uint64_t> FramePattern::match(const std::string& name) const {
    if (name.size() <= prefix.size() + suffix.size()) return std::nullopt;
    if (!name.starts_with(prefix) || !name.ends_with(suffix)) return std::nullopt;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), is_digit)) return std::nullopt;
    const std::uint64_t number = std::stoull(digits);
    // Exactly what printf would write: rejects cloth.007.ply for %04d, cloth.01.ply for %d.
    if (file_name(number) != name) return std::nullopt;
    return number;
}

std::optional<FramePattern> parse_frame_pattern(const std::string& spec) {
    const std::filesystem::path path(spec);
    const std::string name = path.filename().string();
    const std::optional<Field> field = find_field(name, 0);
    if (!field) return std::nullopt;
    if (find_field(name, field->start + field->length)) {
        throw InputError(spec + ": more than one frame number field");
    }
    FramePattern pattern;
    pattern.directory = path.parent_path();
    pattern.prefix = name.substr(0, field->start);
    pattern.suffix = name.substr(field->start + field->length);
    pattern.width = field->width;
    return pattern;
}

std::vector<std::filesystem::path> expand_frame_pattern(const FramePattern& pattern,
                                                        const std::string& spec) {
    const std::filesystem::path directory =
        pattern.directory.empty() ? std::filesystem::path(".") : pattern.directory;
    std::set<std::uint64_t> numbers;
    std::error_code error;
    for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        if (!it->is_regular_file(error)) continue;
        if (const auto number = pattern.match(it->path().filename().string())) numbers.insert(*number);
    }
    if (numbers.empty()) throw InputError(spec + ": no file matches this frame pattern");
    // A gap would silently drop every frame after it: say which file is missing instead.
    const std::uint64_t first = *numbers.begin(), last = *numbers.rbegin();
    if (last - first + 1 != numbers.size()) {
        std::uint64_t missing = first;
        while (numbers.contains(missing)) ++missing;
        throw InputError(spec + ": frame file " + (pattern.directory / pattern.file_name(missing)).string() +
                         " is missing, but " + pattern.file_name(last) + " exists: expected consecutive frames " +
                         std::to_string(first) + " to " + std::to_string(last));
    }
    std::vector<std::filesystem::path> files;
    for (std::uint64_t number = first; number <= last; ++number) {
        files.push_back(pattern.directory / pattern.file_name(number));
    }
    return files;
}

std::string object_name_from(const std::string& file_name) {
    std::string name = file_name;
    if (const std::optional<Field> field = find_field(name, 0)) name.erase(field->start, field->length);
    name = strip_extensions(name);
    const std::string separators = "._- ";
    const std::size_t first = name.find_first_not_of(separators);
    if (first == std::string::npos) return "object";
    const std::size_t last = name.find_last_not_of(separators);
    return name.substr(first, last + 1 - first);
}

}  // namespace collidescope
