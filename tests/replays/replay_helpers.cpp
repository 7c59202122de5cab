// Helpers of the replayer's tests.

#include "replay_helpers.hpp"

#include "support/cli_runner.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image.h>
#pragma GCC diagnostic pop

#include <fstream>
#include <sstream>

namespace collidescope::testing {

Image read_png(const std::filesystem::path& file) {
    Image image;
    int channels = 0;
    unsigned char* data = stbi_load(file.c_str(), &image.width, &image.height, &channels, 4);
    if (data == nullptr) return Image{};
    image.rgba.assign(data, data + std::size_t(image.width) * std::size_t(image.height) * 4);
    stbi_image_free(data);
    return image;
}

std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

bool is_collision_colour(const std::uint8_t* p) { return p[0] > 90 && p[1] * 3 < p[0] && p[2] * 3 < p[0]; }
bool is_diff_colour(const std::uint8_t* p) { return p[1] > 90 && p[0] * 2 < p[1] && p[2] * 2 < p[1]; }
bool is_background(const std::uint8_t* p) { return p[0] == 28 && p[1] == 31 && p[2] == 36; }
bool is_bright(const std::uint8_t* p) { return p[0] > 150 && p[1] > 150 && p[2] > 150; }

void record(const std::string& scene, const std::string& method, const std::filesystem::path& file,
            const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"record", "--scene", scene, "--method", method, "-o", file.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult result = run_cli(args, file.parent_path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
}

void overwrite_pair_element(const std::filesystem::path& file, std::uint64_t row, int column, std::uint32_t value) {
    const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(h5, 0) << file;
    const hid_t dataset = H5Dopen2(h5, "/collisions/pairs", H5P_DEFAULT);
    ASSERT_GE(dataset, 0);
    const hid_t space = H5Dget_space(dataset);
    const hsize_t start[2] = {row, hsize_t(column)};
    const hsize_t count[2] = {1, 1};
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t memory = H5Screate_simple(2, count, nullptr);
    EXPECT_GE(H5Dwrite(dataset, H5T_NATIVE_UINT32, memory, space, H5P_DEFAULT, &value), 0);
    H5Sclose(memory);
    H5Sclose(space);
    H5Dclose(dataset);
    H5Fclose(h5);
}

void set_time_attributes(const std::filesystem::path& file, double fps, char up_axis) {
    const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(h5, 0) << file;
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t fps_attr = H5Acreate2(h5, "fps", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Awrite(fps_attr, H5T_NATIVE_DOUBLE, &fps), 0);
    H5Aclose(fps_attr);
    const hid_t text = H5Tcopy(H5T_C_S1);
    H5Tset_size(text, 2);
    H5Tset_strpad(text, H5T_STR_NULLTERM);
    const char up[2] = {up_axis, 0};
    const hid_t up_attr = H5Acreate2(h5, "up_axis", text, scalar, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Awrite(up_attr, text, up), 0);
    H5Aclose(up_attr);
    H5Tclose(text);
    H5Sclose(scalar);
    H5Fclose(h5);
}

void add_frame_times(const std::filesystem::path& file, const std::vector<double>& times) {
    const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(h5, 0) << file;
    const hsize_t rows = times.size();
    const hid_t space = H5Screate_simple(1, &rows, nullptr);
    const hid_t dataset = H5Dcreate2(h5, "/frames/time", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()), 0);
    const hid_t text = H5Tcopy(H5T_C_S1);
    H5Tset_size(text, 2);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t unit = H5Acreate2(dataset, "unit", text, scalar, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Awrite(unit, text, "s"), 0);
    H5Aclose(unit);
    H5Sclose(scalar);
    H5Tclose(text);
    H5Dclose(dataset);
    H5Sclose(space);
    H5Fclose(h5);
}

std::filesystem::path test_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("collidescope_replays_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace collidescope::testing
