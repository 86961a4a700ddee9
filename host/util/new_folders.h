// Folders a run may make for its outputs, removed again when the run fails: with OutputBatch
// (whose temporaries are gone by then) a failed run leaves no new folder either.
#pragma once

#include <filesystem>
#include <system_error>
#include <vector>

#include "util/file_io.h"

namespace rc {

class NewFolders {
   public:
    // Notes which of `folders` do not exist yet.
    explicit NewFolders(const std::vector<std::filesystem::path>& folders) {
        for (const std::filesystem::path& folder : folders) {
            std::error_code error;
            if (!std::filesystem::exists(std::filesystem::symlink_status(folder, error))) {
                absent_.push_back(folder);
                note_new_folder(folder);  // a signal removes it too
            }
        }
    }
    NewFolders(const NewFolders&) = delete;
    NewFolders& operator=(const NewFolders&) = delete;

    // The run succeeded: its folders stay.
    void keep() {
        for (const std::filesystem::path& folder : absent_) {
            forget_new_folder(folder);
        }
        absent_.clear();
    }

    // Removes each noted folder that the run made, when it is empty (never anything in it).
    ~NewFolders() {
        for (const std::filesystem::path& folder : absent_) {
            forget_new_folder(folder);
            std::error_code error;
            if (std::filesystem::is_directory(std::filesystem::symlink_status(folder, error)) &&
                std::filesystem::is_empty(folder, error)) {
                std::filesystem::remove(folder, error);
            }
        }
    }

   private:
    std::vector<std::filesystem::path> absent_;
};

}  // namespace rc
