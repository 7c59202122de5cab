#pragma once
// A mesh file's format by its extension (engine/src/mesh, private): what read_mesh_file picks
// its reader by, and what the assimp checks pick a header check by.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace collidescope {

/// `text` in lower case (ASCII).
inline std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

/// The format's extension in lower case, looking through a trailing .gz:
/// "cloth.0001.PLY.gz" -> ".ply".
inline std::string format_extension(const std::filesystem::path& file) {
    const std::string extension = lowercase(file.extension().string());
    if (extension == ".gz") return lowercase(file.stem().extension().string());
    return extension;
}

}  // namespace collidescope
