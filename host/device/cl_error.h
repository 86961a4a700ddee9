// OpenCL status codes as names, and the check every OpenCL call goes through.
#pragma once

#include <string>

namespace rc {

// "CL_OUT_OF_RESOURCES" for -5, and so on; "CL_ERROR_<code>" for codes it does not know.
std::string cl_error_name(int status);

// Throws Error("<call>(<subject>) failed: <status name>") unless status is CL_SUCCESS. `subject`
// names what the call acted on: a kernel, a buffer, a program.
void check_cl(int status, const char* call, const std::string& subject = "");

}  // namespace rc
