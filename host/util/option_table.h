// A method's options as one typed table (docs/command-line.md is generated from these tables):
// each entry is an option's name, value, type, range or choices, unit, one-line help, whether it
// is a quality knob (and which way it buys accuracy for time), and the field of the method's
// options struct it is read into. The default is the field's value in a default-made struct, so
// it is written once, in the struct. The table is read once into that struct after the command
// line is parsed (CLI11 has checked every value against the table's specs); `--help`, the option
// reference, `render --list-knobs` and the foreign-option refusal read the same table.
#pragma once

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "util/cli.h"

namespace rc {

// Which way a quality knob buys accuracy for time.
enum class KnobDirection {
    kNone,      // not a quality knob
    kIncrease,  // a larger value: more accurate, slower (rays per record, samples)
    kDecrease,  // a smaller value: more accurate, slower (accuracy a, spacing, error bounds)
};

const char* knob_direction_name(KnobDirection direction);  // "none", "increase", "decrease"

// What every reader of the table but the parse needs of one option.
struct OptionInfo {
    OptionSpec spec;           // name, value name, help (without its default), accepted values
    std::string type;          // integer, number, choice, flag, text, path, length
    std::string unit;          // rays, pixels, MiB, ...; empty when it has none
    std::string default_text;  // the value when the option is not given (a flag: "off")
    std::string default_note;  // when the default depends on other options: how
    KnobDirection knob = KnobDirection::kNone;

    // The help line with its default: "hemisphere rays per record (default 1024)".
    std::string help_with_default() const;
};

// The shortest text that reads back as `value` ("0.35", "1e-06", "16").
template <class F>
std::string option_value_text(F value) {
    if constexpr (std::is_same_v<F, bool>) {
        return value ? "on" : "off";
    } else if constexpr (std::is_floating_point_v<F>) {
        char buffer[64];
        const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
        return error == std::errc() ? std::string(buffer, end) : std::string("?");
    } else {
        return std::to_string(value);
    }
}

template <class T>
class OptionTable {
   public:
    struct Entry {
        OptionInfo info;
        std::function<void(T&, const ParsedArguments&)> read;
        std::function<std::string(const T&)> text;  // the field's value as the option takes it
    };

    // An integer option in [min, max], read into `field`; `words` are accepted besides
    // integers ("auto") and read as `word_value`.
    template <class F>
    OptionTable& integer(std::string name, std::string value_name, F T::*field, long long min,
                         long long max, std::string help, std::vector<std::string> words = {},
                         F word_value = F{}) {
        const std::string option = name;
        Entry entry;
        entry.info.spec =
            OptionSpec{std::move(name), "", std::move(value_name), std::move(help)}.integers(
                min, max, words);
        entry.info.type = "integer";
        entry.read = [option, field, words, word_value](T& options, const ParsedArguments& a) {
            if (!a.has(option)) {
                return;
            }
            for (const std::string& word : words) {
                if (a.value(option) == word) {
                    options.*field = word_value;
                    return;
                }
            }
            options.*field = static_cast<F>(a.integer(option, 0));
        };
        entry.text = [field, words, word_value](const T& options) {
            if (!words.empty() && options.*field == word_value) {
                return words.front();
            }
            return option_value_text(options.*field);
        };
        return add(std::move(entry));
    }

    // A number option in [min, max], read into `field`.
    template <class F>
    OptionTable& number(std::string name, std::string value_name, F T::*field, double min,
                        double max, std::string help) {
        const std::string option = name;
        Entry entry;
        entry.info.spec =
            OptionSpec{std::move(name), "", std::move(value_name), std::move(help)}.numbers(min,
                                                                                            max);
        entry.info.type = "number";
        entry.read = [option, field](T& options, const ParsedArguments& a) {
            if (a.has(option)) {
                options.*field = static_cast<F>(a.number(option, 0.0));
            }
        };
        entry.text = [field](const T& options) { return option_value_text(options.*field); };
        return add(std::move(entry));
    }

    // An option whose value is one of `choices` (word and the field's value for it).
    template <class F>
    OptionTable& choice(std::string name, F T::*field,
                        std::vector<std::pair<std::string, F>> choices, std::string help) {
        const std::string option = name;
        std::vector<std::string> words;
        std::string value_name;
        for (const auto& [word, value] : choices) {
            words.push_back(word);
            value_name += (value_name.empty() ? "" : "|") + word;
        }
        Entry entry;
        entry.info.spec =
            OptionSpec{std::move(name), "", value_name, std::move(help)}.one_of(words);
        entry.info.type = "choice";
        entry.read = [option, field, choices](T& options, const ParsedArguments& a) {
            if (!a.has(option)) {
                return;
            }
            for (const auto& [word, value] : choices) {
                if (a.value(option) == word) {
                    options.*field = value;
                    return;
                }
            }
            throw std::logic_error(option + ": a value its check accepted has no choice");
        };
        entry.text = [field, choices](const T& options) {
            for (const auto& [word, value] : choices) {
                if (options.*field == value) {
                    return word;
                }
            }
            return std::string("?");
        };
        return add(std::move(entry));
    }

    // on|off, read into a bool.
    OptionTable& on_off(std::string name, bool T::*field, std::string help) {
        return choice<bool>(std::move(name), field, {{"on", true}, {"off", false}},
                            std::move(help));
    }

    // A flag: given, the field is true.
    OptionTable& flag(std::string name, bool T::*field, std::string help) {
        const std::string option = name;
        Entry entry;
        entry.info.spec = OptionSpec{std::move(name), "", "", std::move(help)};
        entry.info.type = "flag";
        entry.read = [option, field](T& options, const ParsedArguments& a) {
            if (a.has(option)) {
                options.*field = true;
            }
        };
        entry.text = [field](const T& options) {
            return std::string(options.*field ? "on" : "off");
        };
        return add(std::move(entry));
    }

    // A value parsed by `parse` (which throws Error naming the option for a bad one) and written
    // back by `print`: file paths, lengths with units, grid resolutions.
    template <class F>
    OptionTable& parsed(std::string name, std::string value_name, F T::*field, std::string type,
                        std::function<F(const std::string&)> parse,
                        std::function<std::string(const F&)> print, std::string help) {
        const std::string option = name;
        Entry entry;
        entry.info.spec = OptionSpec{std::move(name), "", std::move(value_name), std::move(help)};
        entry.info.type = std::move(type);
        entry.read = [option, field, parse](T& options, const ParsedArguments& a) {
            if (a.has(option)) {
                options.*field = parse(a.value(option));
            }
        };
        entry.text = [field, print](const T& options) { return print(options.*field); };
        return add(std::move(entry));
    }

    // A file path (empty: none).
    OptionTable& path(std::string name, std::filesystem::path T::*field, std::string help) {
        return parsed<std::filesystem::path>(
            std::move(name), "FILE", field, "path",
            [](const std::string& text) { return std::filesystem::path(text); },
            [](const std::filesystem::path& value) { return value.string(); }, std::move(help));
    }

    // The last entry's unit, quality-knob direction, or note on a default that depends on
    // other options.
    OptionTable& unit(std::string unit) {
        entries_.back().info.unit = std::move(unit);
        return *this;
    }
    OptionTable& knob(KnobDirection direction) {
        entries_.back().info.knob = direction;
        return *this;
    }
    OptionTable& default_note(std::string note) {
        entries_.back().info.default_note = std::move(note);
        return *this;
    }

    // Every entry of `table`, over the member `member` of T.
    template <class U>
    OptionTable& include(const OptionTable<U>& table, U T::*member) {
        for (const typename OptionTable<U>::Entry& inner : table.entries()) {
            Entry entry;
            entry.info = inner.info;
            const auto read = inner.read;
            const auto text = inner.text;
            entry.read = [read, member](T& options, const ParsedArguments& a) {
                read(options.*member, a);
            };
            entry.text = [text, member](const T& options) { return text(options.*member); };
            add(std::move(entry));
        }
        return *this;
    }

    // Reads every option given into `options` (the others keep their values).
    void read(const ParsedArguments& arguments, T* options) const {
        for (const Entry& entry : entries_) {
            entry.read(*options, arguments);
        }
    }

    // The options with their defaults: the values of a default-made T.
    std::vector<OptionInfo> infos() const {
        const T defaults{};
        std::vector<OptionInfo> infos;
        for (const Entry& entry : entries_) {
            infos.push_back(entry.info);
            infos.back().default_text = entry.text(defaults);
        }
        return infos;
    }

    const std::vector<Entry>& entries() const { return entries_; }

   private:
    OptionTable& add(Entry entry) {
        for (const Entry& existing : entries_) {
            if (existing.info.spec.name == entry.info.spec.name) {
                throw std::logic_error(entry.info.spec.name + " declared twice in one table");
            }
        }
        entries_.push_back(std::move(entry));
        return *this;
    }

    std::vector<Entry> entries_;
};

}  // namespace rc
