#include "util/output_identity.h"

#include <sys/stat.h>

#include <limits>
#include <optional>

#include "util/error.h"

namespace rc {
namespace {

// What makes two paths one file: the file they name where it exists, else the path itself.
struct Identity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string normal;  // absolute, lexically normal, symlinks of existing folders resolved
};

Identity identity_of(const std::filesystem::path& path) {
    Identity identity;
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0) {
        identity.exists = true;
        identity.device = info.st_dev;
        identity.inode = info.st_ino;
    }
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, error);
    identity.normal = (error ? absolute : canonical).lexically_normal().string();
    return identity;
}

bool same_file(const Identity& a, const Identity& b) {
    if (a.exists && b.exists && a.device == b.device && a.inode == b.inode) {
        return true;
    }
    return a.normal == b.normal;
}

// The frame number `name` is the frame_path of `pattern` for, if any.
std::optional<long long> frame_of(const std::string& pattern, const std::string& name) {
    const size_t hash = pattern.find('#');
    if (hash == std::string::npos) {
        return std::nullopt;
    }
    const size_t end = pattern.find_first_not_of('#', hash);
    const std::string prefix = pattern.substr(0, hash);
    const std::string suffix = end == std::string::npos ? "" : pattern.substr(end);
    if (name.size() < prefix.size() + suffix.size() + 1 || name.compare(0, hash, prefix) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
        return std::nullopt;
    }
    const std::string middle =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    const size_t sign = middle[0] == '-' ? 1 : 0;
    if (middle.size() <= sign || middle.size() > 12 ||
        middle.find_first_not_of("0123456789", sign) != std::string::npos) {
        return std::nullopt;
    }
    const long long number = std::stoll(middle);
    if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max() ||
        frame_path(pattern, static_cast<int>(number)).string() != name) {
        return std::nullopt;
    }
    return number;
}

// Error (exit status 2): output `option` `path` is input or output `other`.
[[noreturn]] void refuse(const std::string& option, const std::filesystem::path& path,
                         const std::string& other, const std::filesystem::path& other_path,
                         bool other_is_input) {
    const std::string named =
        other_path.string() == path.string() ? "" : " (" + other_path.string() + ")";
    throw Error(
        option + " " + path.string() + ": " +
            (other_is_input
                 ? "is the run's " + other + named + "; refusing to overwrite an input"
                 : "is also the output of " + other + named + "; refusing to write one file twice"),
        kExitUsage);
}

}  // namespace

std::filesystem::path frame_path(const std::string& pattern, int frame) {
    const size_t first = pattern.find('#');
    if (first == std::string::npos) {
        return pattern;
    }
    const size_t last = pattern.find_first_not_of('#', first);
    const size_t width = (last == std::string::npos ? pattern.size() : last) - first;
    // The frame number zero-padded to the run's width (any width: the 40 '#').
    const std::string digits = std::to_string(frame < 0 ? -static_cast<long long>(frame) : frame);
    const size_t sign = frame < 0 ? 1 : 0;
    const std::string number =
        (frame < 0 ? "-" : "") +
        std::string(width > digits.size() + sign ? width - digits.size() - sign : 0, '0') + digits;
    return pattern.substr(0, first) + number + pattern.substr(first + width);
}

void RunFiles::input(const std::string& what, const std::filesystem::path& path) {
    inputs_.push_back({what, path});
}

void RunFiles::output(const std::string& option, const std::filesystem::path& path) {
    outputs_.push_back({option, path});
}

void RunFiles::output_frames(const std::string& option, const std::string& pattern, int first,
                             int last) {
    if (first == last || pattern.find('#') == std::string::npos) {
        output(option, frame_path(pattern, first));
        return;
    }
    frames_.push_back({option, pattern, first, last});
}

void RunFiles::check() const {
    std::vector<Identity> inputs;
    for (const File& file : inputs_) {
        inputs.push_back(identity_of(file.path));
    }
    // Each single output against the inputs, the earlier outputs and the frame sequences.
    std::vector<Identity> outputs;
    for (const File& file : outputs_) {
        const Identity identity = identity_of(file.path);
        for (size_t i = 0; i < inputs.size(); ++i) {
            if (same_file(identity, inputs[i])) {
                refuse(file.role, file.path, inputs_[i].role, inputs_[i].path, true);
            }
        }
        for (size_t i = 0; i < outputs.size(); ++i) {
            if (same_file(identity, outputs[i])) {
                refuse(file.role, file.path, outputs_[i].role, outputs_[i].path, false);
            }
        }
        for (const Frames& frames : frames_) {
            const std::string pattern = identity_of(frames.pattern).normal;
            const std::optional<long long> frame = frame_of(pattern, identity.normal);
            if (frame && *frame >= frames.first && *frame <= frames.last) {
                refuse(file.role, file.path, frames.option,
                       frame_path(frames.pattern, static_cast<int>(*frame)), false);
            }
        }
        outputs.push_back(identity);
    }
    // Each frame sequence against the inputs: by name, and by identity for the frames that
    // exist (a hard link or symlink beside them).
    for (const Frames& frames : frames_) {
        const std::string pattern = identity_of(frames.pattern).normal;
        const auto in_range = [&](const std::string& name) {
            const std::optional<long long> frame = frame_of(pattern, name);
            return frame && *frame >= frames.first && *frame <= frames.last ? frame : std::nullopt;
        };
        for (size_t i = 0; i < inputs.size(); ++i) {
            if (const auto frame = in_range(inputs[i].normal)) {
                refuse(frames.option, frame_path(frames.pattern, static_cast<int>(*frame)),
                       inputs_[i].role, inputs_[i].path, true);
            }
        }
        const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
        if (pattern.rfind('/') > pattern.find('#')) {
            continue;  // '#' in a folder's name: the frames are compared by name only
        }
        std::error_code error;
        for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
             entry.increment(error)) {
            const auto frame = in_range(entry->path().string());
            if (!frame) {
                continue;
            }
            const Identity identity = identity_of(entry->path());
            for (size_t i = 0; i < inputs.size(); ++i) {
                if (same_file(identity, inputs[i])) {
                    refuse(frames.option, frame_path(frames.pattern, static_cast<int>(*frame)),
                           inputs_[i].role, inputs_[i].path, true);
                }
            }
        }
    }
}

}  // namespace rc
