#include "device/fault_injection.h"

#include <mutex>

namespace rc {
namespace {

struct FaultState {
    std::mutex mutex;
    std::string api;  // empty: disarmed
    uint64_t nth = 0;
    int status = 0;
    uint64_t seen = 0;  // calls of `api` since arming
    bool fired = false;
    std::map<std::string, uint64_t, std::less<>> api_calls;
    std::map<std::string, DeviceCallSite> sites;
    std::map<std::string, long long, std::less<>> live;
};

// Never destroyed: OpenCL objects held by other statics (a test's shared contexts, made before the
// first call here) are released during static destruction, after a function-local static made
// later would already be gone.
FaultState& state() {
    static FaultState* const fault = new FaultState;
    return *fault;
}

}  // namespace

void arm_device_fault(const std::string& api, uint64_t nth, int status) {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.api = api;
    s.nth = nth;
    s.status = status;
    s.seen = 0;
    s.fired = false;
}

void disarm_device_fault() { arm_device_fault("", 0, 0); }

bool device_fault_fired() {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.fired;
}

std::map<std::string, DeviceCallSite> device_call_sites() {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.sites;
}

void reset_device_call_counts() {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.api_calls.clear();
    s.sites.clear();
}

std::map<std::string, long long> live_device_objects() {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return {s.live.begin(), s.live.end()};
}

int injected_device_status(std::string_view api, std::string_view site) {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    const std::string name(api);
    const uint64_t call = ++s.api_calls[name];
    const size_t slash = site.rfind('/');
    DeviceCallSite& counted =
        s.sites[name + "@" +
                std::string(slash == std::string_view::npos ? site : site.substr(slash + 1))];
    counted.api = name;
    counted.first_call = counted.calls == 0 ? call : counted.first_call;
    counted.last_call = call;
    ++counted.calls;
    if (s.api.empty() || s.api != api || ++s.seen != s.nth) {
        return 0;
    }
    s.fired = true;
    return s.status;
}

void note_device_object(std::string_view kind, int delta) {
    FaultState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    const auto found = s.live.find(kind);
    if (found == s.live.end()) {
        s.live.emplace(std::string(kind), delta);
    } else {
        found->second += delta;
    }
}

}  // namespace rc
