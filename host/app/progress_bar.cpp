#include "app/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace rc {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)),
      active_(enabled && ::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double fraction, const std::string& detail) {
    if (!active_) {
        return;
    }
    constexpr int kWidth = 30;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kWidth);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "\r%s [%s] %3d%% %s %.1f s\033[K", label_.c_str(), bar.c_str(),
                 static_cast<int>(fraction * 100.0), detail.c_str(), seconds);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (active_ && drawn_) {
        std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }
    drawn_ = false;
}

}  // namespace rc
