#include "util/stderr_capture.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "util/text.h"

namespace rc {

namespace {

std::mutex& capture_turns() {
    static std::mutex turns;
    return turns;
}

}  // namespace

StderrCapture::StderrCapture() : turn_(capture_turns()) {
    std::fflush(stderr);
    char name[] = "/tmp/radcache-stderr-XXXXXX";
    capture_fd_ = ::mkstemp(name);
    if (capture_fd_ < 0) {
        return;
    }
    ::unlink(name);
    saved_fd_ = ::dup(STDERR_FILENO);
    if (saved_fd_ < 0 || ::dup2(capture_fd_, STDERR_FILENO) < 0) {
        ::close(capture_fd_);
        capture_fd_ = -1;
        if (saved_fd_ >= 0) {
            ::close(saved_fd_);
            saved_fd_ = -1;
        }
    }
}

StderrCapture::~StderrCapture() { finish(); }

std::string StderrCapture::finish_text(size_t limit) {
    if (capture_fd_ < 0) {
        if (turn_.owns_lock()) {
            turn_.unlock();
        }
        return "";
    }
    std::fflush(stderr);
    ::dup2(saved_fd_, STDERR_FILENO);
    ::close(saved_fd_);
    saved_fd_ = -1;
    std::string text;
    char chunk[4096];
    ::lseek(capture_fd_, 0, SEEK_SET);
    for (ssize_t got;
         text.size() < limit && (got = ::read(capture_fd_, chunk, sizeof chunk)) > 0;) {
        text.append(chunk, static_cast<size_t>(got));
    }
    ::close(capture_fd_);
    capture_fd_ = -1;
    turn_.unlock();
    return text.substr(0, limit);
}

std::string StderrCapture::finish() {
    const std::string text = finish_text(4096);
    std::string joined;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end;
        if (end > start) {
            joined += (joined.empty() ? "" : "; ") + text.substr(start, end - start);
        }
        start = end + 1;
    }
    return excerpt(joined, 2 * kQuoteLimit);
}

}  // namespace rc
