#pragma once
// Helpers of the mesh and scene tests: a per-test temporary directory, files written by
// hand (text or bytes in either byte order), and capturing an InputError's message.

#include "collidescope/error.hpp"
#include "collidescope/mesh.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope::testing_files {

/// A fresh directory under the system temp dir, named after the test and the process;
/// removed with everything in it when the test ends.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        const std::string name = std::string("collidescope_") + info->test_suite_name() + "_" +
                                 info->name() + "_" + std::to_string(::getpid());
        m_path = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~TempDir() {
        std::error_code error;
        std::filesystem::remove_all(m_path, error);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

private:
    std::filesystem::path m_path;
};

/// "prefix" + number zero-padded to `width` digits + "suffix", e.g. ("cloth.", 7, ".ply", 4).
inline std::string numbered_name(std::string_view prefix, int number, std::string_view suffix,
                                 int width = 0) {
    std::string digits = std::to_string(number);
    if (digits.size() < static_cast<std::size_t>(width)) {
        digits.insert(0, static_cast<std::size_t>(width) - digits.size(), '0');
    }
    std::string name(prefix);
    name += digits;
    name += suffix;
    return name;
}

inline void write_text(const std::filesystem::path& file, std::string_view text) {
    std::ofstream out(file, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    ASSERT_TRUE(out.good()) << file;
}

inline void write_bytes(const std::filesystem::path& file, const std::vector<std::byte>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << file;
}

/// Builds binary files by hand, in either byte order.
class ByteWriter {
public:
    explicit ByteWriter(bool big_endian = false) : m_big_endian(big_endian) {}

    void text(std::string_view s) {
        for (const char c : s) m_bytes.push_back(static_cast<std::byte>(c));
    }
    template <class T>
    void put(T value) {
        std::byte raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        const bool swap = m_big_endian != (std::endian::native == std::endian::big);
        for (std::size_t i = 0; i < sizeof(T); ++i) m_bytes.push_back(raw[swap ? sizeof(T) - 1 - i : i]);
    }
    const std::vector<std::byte>& bytes() const { return m_bytes; }
    std::span<const std::byte> span() const { return m_bytes; }

private:
    bool m_big_endian;
    std::vector<std::byte> m_bytes;
};

inline std::span<const std::byte> as_bytes(std::string_view text) {
    return {reinterpret_cast<const std::byte*>(text.data()), text.size()};
}

/// Runs `action`, expects an InputError and returns its message ("" and a failure otherwise).
template <class Action>
std::string input_error(Action&& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
}

}  // namespace collidescope::testing_files
