// The enum options on the command line take their names from the engine's tables
// (collidescope/option_names.hpp): each name sets its enumerator, an unknown name is a usage
// error, and the help shows the default by name.

#include "engine_cli_options.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace collidescope::app {
namespace {

// Parses `args` after a program name into fresh engine options.
EngineOptions parse(std::vector<std::string> args) {
    CLI::App app;
    EngineOptions options;
    add_engine_options(app, options);
    args.insert(args.begin(), "collidescope");
    std::vector<const char*> argv;
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    app.parse(static_cast<int>(argv.size()), argv.data());
    return options;
}

TEST(NamedOptions, DefaultsAreTheEngines) {
    const EngineOptions options = parse({});
    EXPECT_EQ(options.aabb.builder, AabbOptions{}.builder);
    EXPECT_EQ(options.aabb.rebuild, AabbOptions{}.rebuild);
    EXPECT_EQ(options.aabb.background, AabbOptions{}.background);
    EXPECT_EQ(options.policy, AdaptiveOptions{}.policy);
    EXPECT_EQ(options.gpu.cull, GpuCullConfig{}.variant);
    EXPECT_EQ(options.gpu.gl, GpuCullConfig{}.gl);
}

// Every name of every table, given on the command line, sets its enumerator.
TEST(NamedOptions, EveryNameSetsItsValue) {
    for (const auto& entry : k_aabb_builder_names) {
        EXPECT_EQ(parse({"--aabb-builder", std::string(entry.name)}).aabb.builder, entry.value) << entry.name;
    }
    for (const auto& entry : k_aabb_rebuild_rule_names) {
        EXPECT_EQ(parse({"--rebuild-policy", std::string(entry.name)}).aabb.rebuild, entry.value) << entry.name;
    }
    for (const auto& entry : k_aabb_background_names) {
        EXPECT_EQ(parse({"--background-rebuild", std::string(entry.name)}).aabb.background, entry.value) << entry.name;
    }
    for (const auto& entry : k_adaptive_policy_names) {
        EXPECT_EQ(parse({"--policy", std::string(entry.name)}).policy, entry.value) << entry.name;
    }
    for (const auto& entry : k_gpu_cull_variant_names) {
        EXPECT_EQ(parse({"--gpu-cull", std::string(entry.name)}).gpu.cull, entry.value) << entry.name;
    }
    for (const auto& entry : k_gl_backend_names) {
        EXPECT_EQ(parse({"--gl", std::string(entry.name)}).gpu.gl, entry.value) << entry.name;
    }
}

TEST(NamedOptions, UnknownNamesAreUsageErrors) {
    for (const char* flag :
         {"--aabb-builder", "--rebuild-policy", "--background-rebuild", "--policy", "--gpu-cull", "--gl"}) {
        EXPECT_THROW(parse({flag, "no-such-name"}), CLI::ValidationError) << flag;
    }
}

TEST(NamedOptions, HelpShowsDefaultsByName) {
    CLI::App app;
    EngineOptions options;
    add_engine_options(app, options);
    const std::string help = app.help();
    for (const std::string expected :
         {"--aabb-builder TEXT:{lbvh,sah}=lbvh", "--rebuild-policy TEXT:{quality,thesis,never}=quality",
          "--background-rebuild TEXT:{auto,on,off}=auto", "--policy TEXT:{thesis,cost}=cost",
          "--gpu-cull TEXT:{queries,flags}=queries", "--gl TEXT:{auto,osmesa,egl}=auto"}) {
        EXPECT_NE(help.find(expected), std::string::npos) << expected << "\n" << help;
    }
}

}  // namespace
}  // namespace collidescope::app
