// radcache: global illumination with illumination caching on OpenCL devices.
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "util/error.h"

namespace {

const char* kUsage =
    "usage: radcache COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  devices          list the OpenCL platforms and devices\n"
    "  render SCENE     render a scene to an image\n"
    "  compare TEST REF an image's error against a reference\n"
    "  convert IN OUT.json  a glTF scene in radcache's scene format\n"
    "  warmup           build the kernel programs a render needs into the binary cache\n"
    "  bench all        every kernel family on every device, side by side\n"
    "  bench rays       traversal throughput against Embree\n"
    "  bench pt         path-tracing throughput\n"
    "  bench sh         radiance caching's spherical harmonics: projection, rotation, BRDF tables\n"
    "  bench compile    cold and warm kernel build times\n"
    "\n"
    "radcache COMMAND --help describes a command's options.\n";

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h") {
        std::cout << kUsage;
        return words.empty() ? rc::kExitUsage : 0;
    }
    const std::vector<std::string> args(words.begin() + 1, words.end());
    try {
        if (words[0] == "devices") {
            return rc::run_devices_command(args);
        }
        if (words[0] == "render") {
            return rc::run_render_command(args);
        }
        if (words[0] == "convert") {
            return rc::run_convert_command(args);
        }
        if (words[0] == "compare") {
            return rc::run_compare_command(args);
        }
        if (words[0] == "warmup") {
            return rc::run_warmup_command(args);
        }
        if (words[0] == "bench") {
            return rc::run_bench_command(args);
        }
        if (words[0] == "--version") {
            std::cout << "radcache 0.1.0\n";
            return 0;
        }
        std::cerr << "radcache: error: unknown command '" << words[0] << "'\n" << kUsage;
        return rc::kExitUsage;
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
