// Captures what libraries print on stderr (libpng's "libpng error: ..." lines) while an object of
// this type lives, so that it can go into radcache's one error line instead of before it.
// stderr is the process's: captures on several threads (programs built in the background) take
// turns, each holding a process-wide lock from construction to finish.
#pragma once

#include <mutex>
#include <string>

namespace rc {

class StderrCapture {
   public:
    StderrCapture();   // from here on, stderr goes to a temporary file
    ~StderrCapture();  // stderr restored; what was captured and not taken is dropped
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // Restores stderr and returns what was printed meanwhile, its lines joined by "; " (empty
    // when nothing was, or when stderr could not be redirected).
    std::string finish();
    // Restores stderr and returns what was printed meanwhile as it was printed (its first
    // `limit` bytes).
    std::string finish_text(size_t limit = 65536);

   private:
    std::unique_lock<std::mutex> turn_;
    int saved_fd_ = -1;
    int capture_fd_ = -1;
};

}  // namespace rc
