// The message of the rc::Error a piece of work throws: what the tests of refused inputs compare.
#pragma once

#include <string>

#include "util/error.h"

namespace rc::test {

// The Error message of `work()`, or "" when it does not throw.
template <class Work>
std::string error_of(const Work& work) {
    try {
        work();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

}  // namespace rc::test
