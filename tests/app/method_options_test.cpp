// The methods' option tables (host/util/option_table.h), over every method of the registry and
// every option of its table: the default the table states is the value a default-made options
// struct holds and one the option accepts; a value given is read into that option's field and no
// other's (the field printed back is the value given); a value out of range is refused while
// parsing, naming the option and its range; another method's option is refused naming the
// methods it belongs to; the generated help and docs/command-line.md contain every option; and
// --list-knobs lists exactly the table's quality knobs.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/commands.h"
#include "app/option_reference.h"
#include "methods/registry.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

// The command line's options of `words` as the render command parses them.
ParsedArguments parsed(const std::vector<std::string>& words) {
    ParsedArguments arguments;
    for (size_t i = 0; i < words.size(); ++i) {
        for (const OptionSpec& spec : method_option_specs()) {
            if (spec.name != words[i]) {
                continue;
            }
            if (spec.value_name.empty()) {
                arguments.add(spec, {});
            } else {
                EXPECT_EQ(check_value(spec.check, words.at(i + 1)), "") << words[i];
                arguments.add(spec, {words.at(i + 1)});
            }
        }
    }
    return arguments;
}

// A value the option accepts that is not its default, or "" when the test has none for its type.
std::string other_value(const OptionInfo& info, const std::filesystem::path& dir) {
    const ValueCheck& check = info.spec.check;
    if (check.kind == ValueCheck::Kind::kInteger) {
        const std::string low = std::to_string(check.integer_min);
        return low != info.default_text ? low : std::to_string(check.integer_max);
    }
    if (check.kind == ValueCheck::Kind::kNumber) {
        const std::string low = option_value_text(check.number_min);
        return low != info.default_text ? low : option_value_text(check.number_max);
    }
    if (check.kind == ValueCheck::Kind::kChoice) {
        for (const std::string& word : check.words) {
            if (word != info.default_text) {
                return word;
            }
        }
    }
    if (info.type == "path") {
        return (dir / ("file" + info.spec.name)).string();
    }
    if (info.type == "length") {
        return "0.5u";
    }
    if (info.type == "resolution") {
        return "8x4x2";
    }
    if (info.spec.name == "--glossy") {  // text in its own grammar (methods/caching/glossy_spec.h)
        return "copper=rc,*=sdrc";
    }
    return "";
}

TEST(MethodOptions, EveryTableStatesItsDefaultsAndDeclaresEachOptionOnce) {
    for (const MethodEntry& method : method_registry()) {
        const std::vector<std::string> defaults = method.values(method.read(ParsedArguments{}));
        ASSERT_EQ(defaults.size(), method.table.size()) << method.name;
        for (size_t i = 0; i < method.table.size(); ++i) {
            const OptionInfo& info = method.table[i];
            EXPECT_EQ(info.default_text, defaults[i]) << method.name << " " << info.spec.name;
            EXPECT_FALSE(info.spec.help.empty()) << info.spec.name;
            EXPECT_EQ(info.spec.help.find("default"), std::string::npos)
                << info.spec.name << ": the table states the default, not the help";
            // A default the option itself would refuse is a sentinel: it needs a note saying
            // what it means.
            const bool accepted = info.type == "flag" || info.default_text.empty() ||
                                  check_value(info.spec.check, info.default_text).empty();
            EXPECT_TRUE(accepted || !info.default_note.empty())
                << method.name << " " << info.spec.name << " default " << info.default_text;
            for (size_t j = 0; j < i; ++j) {
                EXPECT_NE(method.table[j].spec.name, info.spec.name) << method.name;
            }
        }
    }
}

// Each option given alone is read into its own field: printed back it is the value given, and
// every other option that does not follow another's value keeps its default. A combination the
// method refuses (an option that needs another) is refused naming the option.
TEST(MethodOptions, AValueGivenIsReadIntoItsOwnOptionOnly) {
    const auto dir = test::scratch_dir("method_options_values");
    int read = 0;
    for (const MethodEntry& method : method_registry()) {
        const std::vector<std::string> defaults = method.values(method.read(ParsedArguments{}));
        for (size_t i = 0; i < method.table.size(); ++i) {
            const OptionInfo& info = method.table[i];
            std::vector<std::string> words = {info.spec.name};
            std::string expected = "on";
            if (info.type != "flag") {
                expected = other_value(info, dir);
                ASSERT_FALSE(expected.empty()) << info.spec.name << " has no test value";
                words.push_back(expected);
            }
            std::vector<std::string> values;
            try {
                values = method.values(method.read(parsed(words)));
            } catch (const Error& error) {
                EXPECT_EQ(std::string(error.what()).rfind(info.spec.name, 0), 0u)
                    << method.name << ": " << error.what();
                EXPECT_EQ(error.exit_code(), kExitUsage);
                continue;
            }
            ++read;
            EXPECT_EQ(values[i], expected) << method.name << " " << info.spec.name;
            for (size_t j = 0; j < values.size(); ++j) {
                if (j != i && method.table[j].default_note.empty()) {
                    EXPECT_EQ(values[j], defaults[j]) << method.name << ": " << info.spec.name
                                                      << " changed " << method.table[j].spec.name;
                }
            }
        }
    }
    EXPECT_GT(read, 60);  // most options stand alone
}

// The error of one render command line, parsed in this process (no scene is loaded: values and
// options are checked first; a line wrongly accepted renders a tiny image).
std::string render_error(const std::vector<std::string>& options) {
    const std::string scene = (test::source_dir() / "scenes/cornell-box/scene.json").string();
    const auto out = test::scratch_dir("method_options_render") / "out.png";
    std::vector<std::string> words = {"render",  scene, "-o",       out.string(), "--spp", "1",
                                      "--width", "8",   "--height", "8",          "-q"};
    words.insert(words.end(), options.begin(), options.end());
    try {
        run_command_line(radcache_command_line(), words);
    } catch (const Error& error) {
        EXPECT_EQ(error.exit_code(), kExitUsage) << error.what();
        return error.what();
    }
    return "";
}

TEST(MethodOptions, AValueOutOfRangeIsRefusedNamingTheOptionAndItsRange) {
    for (const MethodEntry& method : method_registry()) {
        for (const OptionInfo& info : method.table) {
            const ValueCheck& check = info.spec.check;
            std::string bad;
            std::string named;
            if (check.kind == ValueCheck::Kind::kInteger) {
                bad = std::to_string(check.integer_max + 1);
                named = "[" + std::to_string(check.integer_min) + ", " +
                        std::to_string(check.integer_max) + "]";
            } else if (check.kind == ValueCheck::Kind::kNumber) {
                bad = option_value_text(check.number_max * 2.0 + 1.0);
                named = "expected a number in [";
            } else if (check.kind == ValueCheck::Kind::kChoice) {
                bad = "bogus";
                named = check.words.front();
            } else {
                continue;
            }
            const std::string error = render_error({"--method", method.name, info.spec.name, bad});
            EXPECT_EQ(error.rfind(info.spec.name + ": expected", 0), 0u) << error;
            EXPECT_NE(error.find(named), std::string::npos) << error;
        }
    }
}

TEST(MethodOptions, AnotherMethodsOptionIsRefusedNamingItsMethods) {
    const auto dir = test::scratch_dir("method_options_foreign");
    int refused = 0;
    for (const MethodEntry& method : method_registry()) {
        for (const MethodEntry& other : method_registry()) {
            for (const OptionInfo& info : other.table) {
                const bool own = std::any_of(
                    method.table.begin(), method.table.end(),
                    [&](const OptionInfo& mine) { return mine.spec.name == info.spec.name; });
                if (own) {
                    continue;
                }
                std::vector<std::string> words = {"--method", method.name, info.spec.name};
                if (info.type != "flag") {
                    words.push_back(other_value(info, dir));
                }
                const std::string error = render_error(words);
                EXPECT_EQ(error.rfind(info.spec.name + " applies to --method ", 0), 0u) << error;
                EXPECT_NE(error.find(other.name), std::string::npos) << error;
                EXPECT_EQ(error.find(" " + method.name + " "), std::string::npos) << error;
                ++refused;
            }
        }
    }
    EXPECT_GT(refused, 100);
}

TEST(MethodOptions, HelpAndTheReferenceListEveryOptionWithItsDefault) {
    const test::CommandResult help = test::run_radcache({"render", "--help"});
    ASSERT_EQ(help.exit_code, 0) << help.output;
    const std::string reference = command_line_reference(radcache_command_line());
    for (const MethodEntry& method : method_registry()) {
        EXPECT_NE(reference.find("### `--method " + method.name + "`"), std::string::npos);
        for (const OptionInfo& info : method.table) {
            EXPECT_NE(help.output.find(info.spec.name), std::string::npos) << info.spec.name;
            EXPECT_NE(help.output.find(info.help_with_default().substr(0, 30)), std::string::npos)
                << info.spec.name;
            EXPECT_NE(reference.find("`" + info.spec.name), std::string::npos) << info.spec.name;
            if (info.type != "flag" && info.default_note.empty() && !info.default_text.empty()) {
                EXPECT_NE(info.help_with_default().find("(default " + info.default_text),
                          std::string::npos)
                    << info.spec.name;
            }
        }
    }
}

// docs/command-line.md is `radcache reference`'s output: regenerate it with
// `build/radcache reference > docs/command-line.md`.
TEST(MethodOptions, TheDocsReferenceIsCurrent) {
    std::ifstream file(test::source_dir() / "docs/command-line.md");
    std::stringstream text;
    text << file.rdbuf();
    EXPECT_TRUE(text.str() == command_line_reference(radcache_command_line()))
        << "docs/command-line.md is stale: run build/radcache reference > docs/command-line.md";
}

TEST(MethodOptions, ListKnobsPrintsTheTablesKnobs) {
    for (const MethodEntry& method : method_registry()) {
        const test::CommandResult result =
            test::run_radcache({"render", "--method", method.name, "--list-knobs", "--json"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const nlohmann::json json = nlohmann::json::parse(result.output);
        EXPECT_EQ(json.at("method"), method.name);
        std::vector<std::string> expected;
        for (const OptionInfo& info : method.table) {
            if (info.knob != KnobDirection::kNone) {
                expected.push_back(info.spec.name);
            }
        }
        std::vector<std::string> listed;
        for (const nlohmann::json& knob : json.at("knobs")) {
            listed.push_back(knob.at("name"));
            EXPECT_NE(knob.at("knob"), "none");
        }
        EXPECT_EQ(listed, expected) << method.name;
    }
    // A method with options that take values has knobs to tune (the shared --spp and --time are
    // every method's; pt's own option is a flag).
    for (const MethodEntry& method : method_registry()) {
        const bool values = std::any_of(method.table.begin(), method.table.end(),
                                        [](const OptionInfo& info) { return info.type != "flag"; });
        EXPECT_TRUE(!values || !knobs_json(method).at("knobs").empty()) << method.name;
    }
}

}  // namespace
}  // namespace rc
