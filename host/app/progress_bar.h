// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>
#include <string>

namespace rc {

class ProgressBar {
   public:
    // `label` precedes the bar ("frame 3"); nothing is drawn when `enabled` is false or stderr
    // is not a terminal.
    ProgressBar(std::string label, bool enabled);
    ~ProgressBar();

    void update(double fraction, const std::string& detail);
    void finish();

   private:
    std::string label_;
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace rc
