// The entries' scratch directory: one per process, so parallel fuzzers never share files.

#include "scratch.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <unistd.h>

namespace collidescope::fuzz {
namespace {

std::filesystem::path make_dir() {
    std::error_code error;
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", error)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    std::string name = (base / "collidescope-fuzz-XXXXXX").string();
    if (mkdtemp(name.data()) == nullptr) std::abort();
    return name;
}

}  // namespace

const std::filesystem::path& scratch_dir() {
    static const std::filesystem::path dir = [] {
        std::filesystem::path made = make_dir();
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(scratch_dir(), ignored);
        });
        return made;
    }();
    return dir;
}

void write_file(const std::filesystem::path& file, std::span<const std::byte> bytes) {
    struct Closer {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    const std::unique_ptr<std::FILE, Closer> stream(std::fopen(file.c_str(), "wb"));
    if (!stream) std::abort();
    if (std::fwrite(bytes.data(), 1, bytes.size(), stream.get()) != bytes.size()) std::abort();
}

}  // namespace collidescope::fuzz
