// The one way host/device/ calls OpenCL: through these macros, so that the test-only fault
// injection (fault_injection.h) can fail any call before the driver runs it, each call is
// counted by its site, and live OpenCL objects are counted for the leak check.
#pragma once

#include <CL/cl.h>

#include "device/fault_injection.h"

#define RC_CL_STRINGIFY_(x) #x
#define RC_CL_STRINGIFY(x) RC_CL_STRINGIFY_(x)
#define RC_CL_SITE __FILE__ ":" RC_CL_STRINGIFY(__LINE__)

// A call that returns its status: RC_CL(clFinish, queue).
#define RC_CL(function, ...) \
    ::rc::cl_status_call(#function, RC_CL_SITE, [&] { return function(__VA_ARGS__); })

// A call that creates an object of `kind` and returns it, with its status through its last
// parameter: RC_CL_CREATE("buffer", clCreateBuffer, &status, context, flags, bytes, nullptr).
#define RC_CL_CREATE(kind, function, status, ...)             \
    ::rc::cl_create_call(kind, #function, RC_CL_SITE, status, \
                         [&](cl_int* status_out) { return function(__VA_ARGS__, status_out); })

// Releases an object of `kind` (never failed by the injection): RC_CL_RELEASE("buffer",
// clReleaseMemObject, handle).
#define RC_CL_RELEASE(kind, function, handle) ::rc::cl_release_call(kind, function(handle))

namespace rc {

template <class Call>
cl_int cl_status_call(const char* api, const char* site, Call call) {
    const int fault = injected_device_status(api, site);
    return fault != 0 ? static_cast<cl_int>(fault) : call();
}

template <class Call>
auto cl_create_call(const char* kind, const char* api, const char* site, cl_int* status, Call call)
    -> decltype(call(status)) {
    const int fault = injected_device_status(api, site);
    if (fault != 0) {
        *status = static_cast<cl_int>(fault);
        return nullptr;
    }
    auto object = call(status);
    if (object != nullptr) {
        note_device_object(kind, +1);
    }
    return object;
}

inline cl_int cl_release_call(const char* kind, cl_int status) {
    note_device_object(kind, -1);
    return status;
}

}  // namespace rc
