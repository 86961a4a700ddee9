// Test-only device fault injection: makes the N-th call of one OpenCL API fail with a
// given status before the driver sees it, as a failing driver would, so that a test can reach
// every call site's error path and check what it reports, frees and leaves behind. Disarmed
// unless a test arms it; disarmed, it only counts calls and live OpenCL objects.
//
// Every OpenCL call of host/device/ goes through cl_calls.h, which consults it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace rc {

// Makes the `nth` call (1-based, counted from the arming) of `api` ("clCreateBuffer") return
// `status` (a CL_* error) instead of calling the driver; later calls run normally.
void arm_device_fault(const std::string& api, uint64_t nth, int status);
void disarm_device_fault();
// Whether the armed fault has been injected since it was armed.
bool device_fault_fired();

// The OpenCL calls of one call site ("context.cpp:131") since the last reset: its API, how many
// times it ran, and the API's call numbers (as arm_device_fault counts them from that reset) of
// its first and last call.
struct DeviceCallSite {
    std::string api;
    uint64_t calls = 0;
    uint64_t first_call = 0;
    uint64_t last_call = 0;
};
// By "api@site".
std::map<std::string, DeviceCallSite> device_call_sites();
// Zeroes the counts (armed faults count from their arming, not from here).
void reset_device_call_counts();

// OpenCL objects created and not yet released, by kind ("buffer", "kernel", "program", "queue",
// "context", "event"): the leak check of the fault sweep.
std::map<std::string, long long> live_device_objects();

// The hooks cl_calls.h uses: the status to fail `api` at `site` with (0: none), counting the
// call; and the creation (+1) or release (-1) of an object of `kind`.
int injected_device_status(std::string_view api, std::string_view site);
void note_device_object(std::string_view kind, int delta);

}  // namespace rc
