// The command line through CLI11 (host/app/command_line.cpp): values checked against their
// declarations while parsing, CLI11's own errors as radcache's one line naming the option (exit
// status 2), "--", and the declarations themselves (an option declared by several methods is one
// option, so every declaration of it must agree).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "app/commands.h"
#include "test_support.h"

namespace rc {
namespace {

TEST(CommandLine, IntegerValuesAreCheckedAgainstTheirRange) {
    const ValueCheck check = OptionSpec{"--n", "", "N", ""}.integers(-3, 5, {"auto"}).check;
    for (const char* good : {"-3", "0", "5", "auto", "+4"}) {
        EXPECT_EQ(check_value(check, good), "") << good;
    }
    EXPECT_EQ(check_value(check, "6"), "expected an integer in [-3, 5], got '6'");
    for (const char* bad : {"-4", "", "1.5", "2x", "Auto", "99999999999999999999"}) {
        EXPECT_NE(check_value(check, bad), "") << bad;
    }
}

TEST(CommandLine, NumberAndChoiceValuesAreChecked) {
    const ValueCheck number = OptionSpec{"--x", "", "X", ""}.numbers(0.5, 2.0).check;
    for (const char* good : {"0.5", "1", "2", "1e0"}) {
        EXPECT_EQ(check_value(number, good), "") << good;
    }
    for (const char* bad : {"0.49", "2.01", "nan", "inf", "", "1,5"}) {
        EXPECT_NE(check_value(number, bad), "") << bad;
    }
    EXPECT_EQ(check_value(number, "3"), "expected a number in [0.5, 2], got '3'");
    // A bound declared as a float (1e-3f lies above 0.001 as a double) is met by its decimal.
    const ValueCheck float_bound = OptionSpec{"--r", "", "R", ""}.numbers(1e-3f, 16.0f).check;
    EXPECT_EQ(check_value(float_bound, "0.001"), "");
    EXPECT_EQ(check_value(float_bound, "0.00099"),
              "expected a number in [0.001, 16], got '0.00099'");
    const ValueCheck choice = OptionSpec{"--c", "", "NAME", ""}.one_of({"a", "b", "c"}).check;
    EXPECT_EQ(check_value(choice, "b"), "");
    EXPECT_EQ(check_value(choice, "d"), "expected a, b or c, got 'd'");
}

// Reading an option as a number it is not declared as is the declaration's mistake.
TEST(CommandLine, ReadingAnUndeclaredNumberIsRefused) {
    ParsedArguments arguments;
    arguments.add(OptionSpec{"--name", "", "NAME", ""}, {"12"});
    arguments.add(OptionSpec{"--n", "", "N", ""}.integers(1, 100), {"12"});
    EXPECT_EQ(arguments.integer("--n", 0), 12);
    EXPECT_EQ(arguments.integer("--absent", 7), 7);
    EXPECT_THROW(arguments.integer("--name", 0), std::logic_error);
    EXPECT_THROW(arguments.number("--n", 0.0), std::logic_error);
}

struct BadLine {
    std::vector<std::string> args;
    std::string expected;
};

TEST(CommandLine, ParseErrorsAreOneLineNamingTheOption) {
    const auto dir = test::scratch_dir("command_line_bad");
    const std::string scene = (test::source_dir() / "scenes/cornell-box/scene.json").string();
    const std::string out = (dir / "out.png").string();
    const std::vector<BadLine> cases = {
        {{"render", scene, "-o", out, "--spp", "2", "--spp", "3"}, "option --spp given twice"},
        {{"render", scene, "-o", out, "-q", "--quiet"}, "option --quiet given twice"},
        {{"render", scene, "-o", out, "--quiet=1"}, "option --quiet takes no value"},
        {{"render", scene, "-o", out, "-D"}, "option -D needs a value (KEY=VALUE)"},
        {{"render", scene, "-o", out, "--bogus=3"},
         "unknown option '--bogus' for 'radcache render'"},
        {{"render", scene, "-o", out, "--sampler", "halton"},
         "--sampler: expected sobol or independent, got 'halton'"},
        {{"render", scene, "-o", out, "--method", "ic", "--temporal", "--temporal-gradients", "x"},
         "--temporal-gradients: expected interpolated, extrapolated or none, got 'x'"},
        {{"render", scene, "-o", out, "--exposure=65"},
         "--exposure: expected a number in [-64, 64], got '65'"},
        {{"render", "-o", out, "--", scene, "--spp"},
         "radcache render needs exactly one scene file"},
        {{"bench", "rays", "--width", "0"}, "--width: expected an integer in [1, 16384], got '0'"},
        {{"warmup", "--method", "pt", "--local-size", "2000"},
         "--local-size: expected an integer in [1, 1024], got '2000'"},
    };
    for (const BadLine& bad : cases) {
        const test::CommandResult result = test::run_radcache(bad.args);
        EXPECT_EQ(result.exit_code, 2) << bad.expected << "\n" << result.output;
        EXPECT_NE(result.output.find("radcache: error: " + bad.expected), std::string::npos)
            << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(CommandLine, VersionAndHelpExitZero) {
    const test::CommandResult version = test::run_radcache({"--version"});
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.output, "radcache 0.1.0\n");
    const test::CommandResult bench = test::run_radcache({"bench", "rays", "-h"});
    EXPECT_EQ(bench.exit_code, 0);
    EXPECT_EQ(bench.output.rfind("usage: radcache bench rays [options]\n", 0), 0u) << bench.output;
    EXPECT_NE(bench.output.find("  --width N"), std::string::npos) << bench.output;
}

bool same_declaration(const OptionSpec& a, const OptionSpec& b) {
    return a.short_name == b.short_name && a.value_name == b.value_name &&
           a.repeatable == b.repeatable && a.check.kind == b.check.kind &&
           a.check.integer_min == b.check.integer_min &&
           a.check.integer_max == b.check.integer_max && a.check.number_min == b.check.number_min &&
           a.check.number_max == b.check.number_max && a.check.words == b.check.words;
}

// A command's option declared twice (a method option several methods share) is one CLI11 option,
// the first declaration: the others must take and accept the same values.
TEST(CommandLine, AnOptionDeclaredTwiceIsDeclaredAlike) {
    for (const CommandSpec& command : radcache_command_line().commands) {
        std::map<std::string, OptionSpec> first;
        for (const OptionSpec& spec : command.options) {
            const auto [found, inserted] = first.emplace(spec.name, spec);
            EXPECT_TRUE(inserted || same_declaration(found->second, spec))
                << command.name << " " << spec.name;
        }
    }
}

}  // namespace
}  // namespace rc
