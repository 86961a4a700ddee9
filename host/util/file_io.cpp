#include "util/file_io.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "util/error.h"
#include "util/interrupt_cleanup.h"

namespace rc {
namespace {

// Closes a file descriptor on every path out of read_file.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) {
            ::close(fd);
        }
    }
};

std::string described(const std::filesystem::path& path, const std::string& what) {
    return what.empty() ? path.string() : path.string() + " (" + what + ")";
}

// The staged files of the open OutputBatch: (temporary, final path) in the order written.
struct StagedFiles {
    // Held while a temporary is written and staged or renamed (before `mutex`), so that a signal
    // finds every temporary either staged or gone (util/interrupt_cleanup.h).
    std::recursive_mutex writing;
    std::mutex mutex;
    bool open = false;
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files;
    std::vector<std::string> folders;  // made by the run (note_new_folder), innermost last
};

StagedFiles& staged() {
    // Never destroyed: the signal thread may use it while the process exits.
    static StagedFiles* files = new StagedFiles;
    return *files;
}

// The signal thread: waits for one of `signals`, removes the staged temporaries once no write is
// in progress, then dies by the signal as the process would have without it.
void remove_staged_outputs_and_die(sigset_t signals) {
    int signal = 0;
    while (::sigwait(&signals, &signal) != 0) {
    }
    StagedFiles& batch = staged();
    batch.writing.lock();  // step 1: no file is being written; none is written again
    batch.mutex.lock();    // step 2: no commit is renaming; remove what is staged
    for (const auto& file : batch.files) {
        ::unlink(file.first.c_str());
    }
    for (auto folder = batch.folders.rbegin(); folder != batch.folders.rend(); ++folder) {
        ::rmdir(folder->c_str());  // only an empty one goes
    }
    // Step 3: the default action, delivered to this thread alone (the others block it).
    std::signal(signal, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, signal);
    ::pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    ::raise(signal);
    ::_exit(128 + signal);
}

void remove_quietly(const std::filesystem::path& path) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}

void rename_or_throw(const std::filesystem::path& temporary, const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        throw Error(path.string() + ": cannot write file: " + error.message());
    }
}

// Keeps `temporary` for the open batch's commit; false when no batch is open.
bool stage(const std::filesystem::path& temporary, const std::filesystem::path& path) {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    if (!batch.open) {
        return false;
    }
    for (auto& [old_temporary, old_path] : batch.files) {
        if (old_path == path) {
            remove_quietly(old_temporary);
            old_temporary = temporary;
            return true;
        }
    }
    batch.files.emplace_back(temporary, path);
    return true;
}

}  // namespace

std::string read_file(const std::filesystem::path& path, uint64_t max_bytes,
                      const std::string& what) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below.
    FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) {
        throw Error(described(path, what) + ": cannot open file: " + std::strerror(errno));
    }
    struct stat info {};
    if (::fstat(file.fd, &info) != 0) {
        throw Error(described(path, what) + ": cannot open file: " + std::strerror(errno));
    }
    if (!S_ISREG(info.st_mode)) {
        throw Error(described(path, what) + ": not a regular file");
    }
    if (static_cast<uint64_t>(info.st_size) > max_bytes) {
        throw Error(described(path, what) + ": " + std::to_string(info.st_size) +
                    " bytes, more than the limit of " + std::to_string(max_bytes));
    }
    // Read to the end, never past the limit (a file may grow, or report size 0 as /proc does).
    std::string bytes;
    bytes.reserve(static_cast<size_t>(info.st_size));
    char chunk[1 << 16];
    for (;;) {
        const ssize_t got = ::read(file.fd, chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            throw Error(described(path, what) + ": read error: " + std::strerror(errno));
        }
        if (got == 0) {
            break;
        }
        if (bytes.size() + static_cast<size_t>(got) > max_bytes) {
            throw Error(described(path, what) + ": more than the limit of " +
                        std::to_string(max_bytes) + " bytes");
        }
        bytes.append(chunk, static_cast<size_t>(got));
    }
    return bytes;
}

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    // Keeps the extension, which some writers use to pick the file variant.
    std::filesystem::path temporary = path;
    temporary.replace_filename(path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter++) + path.extension().string());
    return temporary;
}

void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write,
                             WriteTiming timing) {
    const std::filesystem::path temporary = temporary_sibling(path);
    const std::lock_guard<std::recursive_mutex> writing(staged().writing);
    try {
        write(temporary);
        if (timing == WriteTiming::kWithBatch && stage(temporary, path)) {
            return;
        }
        rename_or_throw(temporary, path);
    } catch (...) {
        remove_quietly(temporary);
        throw;
    }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           WriteTiming timing) {
    replace_file_atomically(
        path,
        [&](const std::filesystem::path& temporary) {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            if (!out) {
                throw Error(path.string() + ": cannot write file: " + std::strerror(errno));
            }
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            out.close();
            if (!out) {
                throw Error(path.string() + ": write error");
            }
        },
        timing);
}

OutputBatch::OutputBatch() {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    if (batch.open) {
        throw Error("internal error: an output batch is already open");
    }
    batch.open = true;
    batch.files.clear();
}

OutputBatch::~OutputBatch() {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    for (const auto& file : batch.files) {
        remove_quietly(file.first);
    }
    batch.files.clear();
    batch.open = false;
}

void OutputBatch::commit() {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    auto files = std::move(batch.files);
    batch.files.clear();
    for (size_t i = 0; i < files.size(); ++i) {
        try {
            rename_or_throw(files[i].first, files[i].second);
        } catch (...) {
            for (size_t j = i; j < files.size(); ++j) {
                remove_quietly(files[j].first);
            }
            throw;
        }
    }
}

void create_output_folder(const std::filesystem::path& folder, std::error_code& error) {
    // Under the write lock, which a signal's cleanup takes and keeps: it never sees a folder
    // made again after it removed it.
    const std::lock_guard<std::recursive_mutex> writing(staged().writing);
    std::filesystem::create_directories(folder, error);
}

void note_new_folder(const std::filesystem::path& folder) {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    batch.folders.push_back(folder.string());
}

void forget_new_folder(const std::filesystem::path& folder) {
    StagedFiles& batch = staged();
    std::lock_guard<std::mutex> lock(batch.mutex);
    batch.folders.erase(std::remove(batch.folders.begin(), batch.folders.end(), folder.string()),
                        batch.folders.end());
}

void remove_staged_outputs_on_signals() {
    static std::once_flag once;
    std::call_once(once, [] {
        sigset_t signals;
        sigemptyset(&signals);
        // Every signal whose default action ends the process and that another process (a
        // shell, `timeout -s`) may send. Not SIGPIPE: tried, a loaded run then once left a
        // temporary (cause not found), so a closed pipe still ends the run at once.
        for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2}) {
            struct sigaction action {};
            if (::sigaction(signal, nullptr, &action) == 0 && action.sa_handler != SIG_IGN) {
                sigaddset(&signals, signal);
            }
        }
        ::pthread_sigmask(SIG_BLOCK, &signals, nullptr);
        std::thread(remove_staged_outputs_and_die, signals).detach();
    });
}

void check_writable_parent(const std::filesystem::path& file, const std::string& option) {
    const std::filesystem::path dir = file.parent_path().empty() ? "." : file.parent_path();
    if (!std::filesystem::is_directory(dir) || ::access(dir.c_str(), W_OK) != 0) {
        throw Error(option + " " + file.string() + ": directory '" + dir.string() +
                        "' does not exist or is not writable",
                    kExitUsage);
    }
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(file, error);
    if (std::filesystem::is_directory(status)) {
        throw Error(option + " " + file.string() + ": is a directory", kExitUsage);
    }
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        throw Error(option + " " + file.string() + ": exists and is not a regular file",
                    kExitUsage);
    }
}

}  // namespace rc
