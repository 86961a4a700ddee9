// radcache: global illumination with illumination caching on OpenCL devices.
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "util/error.h"
#include "util/interrupt_cleanup.h"

int main(int argc, char** argv) {
    // Before any thread starts: an interrupted run leaves no staged temporary.
    rc::remove_staged_outputs_on_signals();
    const std::vector<std::string> words(argv + 1, argv + argc);
    try {
        return rc::run_command_line(rc::radcache_command_line(), words);
    } catch (const rc::Error& error) {
        std::cerr << "radcache: error: " << error.what() << "\n";
        return error.exit_code();
    } catch (const std::bad_alloc&) {
        std::cerr << "radcache: error: out of host memory\n";
        return rc::kExitFailure;
    } catch (const std::exception& error) {
        std::cerr << "radcache: error: " << error.what() << "\n";
        return rc::kExitFailure;
    }
}
