// Guards against the GCC 12.2 -O2 SLP-vectorizer miscompile that dropped a double -> float
// -> double round trip (CMakeLists.txt turns that pass off). The pattern below is the one
// our float32 generators use; without the flag its values stayed unrounded.

#include "collidescope/types.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace collidescope {
namespace {

double round_to_float(double x) { return static_cast<double>(static_cast<float>(x)); }

TEST(Toolchain, FloatRoundTripIsNotOptimisedAway) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto point = [&] {
        return Vec3(round_to_float(unit(rng)), round_to_float(unit(rng)), round_to_float(unit(rng)));
    };
    std::vector<std::pair<std::array<Vec3, 3>, std::array<Vec3, 3>>> pairs(4);
    for (auto& [a, b] : pairs) {
        a = {point(), point(), point()};
        b = {point(), point(), point()};
    }
    for (const auto& [a, b] : pairs)
        for (const auto* t : {&a, &b})
            for (const Vec3& p : *t)
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(p[k], static_cast<double>(static_cast<float>(p[k])));
}

}  // namespace
}  // namespace collidescope
