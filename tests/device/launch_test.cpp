// The one launch function: chunking that never changes results, timing per kernel, and errors
// that name the OpenCL call, the kernel and the status.
#include <gtest/gtest.h>

#include "error_of.h"
#include "shared/rng.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

std::vector<unsigned> words_with(size_t local_size, size_t max_chunk, size_t* launches) {
    Context context(test::chunked_context_options(local_size, max_chunk));
    Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
    const unsigned count = 100003;  // not a multiple of any work-group size
    Buffer<unsigned> out(context, count * 2, "words");
    context.launch(kernel, count, 5u, 6u, 7u, 2u, out);
    *launches = context.kernel_times().at("rng_stream_words").launches;
    EXPECT_EQ(context.kernel_times().at("rng_stream_words").items, count);
    return out.download();
}

TEST(Launch, ChunkingAndWorkGroupSizeNeverChangeResults) {
    size_t launches_default = 0;
    size_t launches_small = 0;
    size_t launches_odd = 0;
    const auto reference = words_with(0, 0, &launches_default);
    EXPECT_EQ(words_with(8, 1000, &launches_small), reference);
    EXPECT_EQ(words_with(16, 4096, &launches_odd), reference);
    EXPECT_GE(launches_small, 100u);  // 100003 items in chunks of at most 1000
    // Every item was computed (the last one too).
    EXPECT_EQ(reference[2 * 100002 + 1], shared::rc_rng_word(5, 6, 100002, 7, 1));
}

TEST(Launch, KernelTimesAreRecorded) {
    Context& context = test::shared_context();
    context.reset_kernel_times();
    Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
    Buffer<unsigned> out(context, 4096, "words");
    context.launch(kernel, 4096, 1u, 2u, 3u, 1u, out);
    const KernelTime& time = context.kernel_times().at("rng_stream_words");
    EXPECT_GE(time.launches, 1u);
    EXPECT_EQ(time.items, 4096u);
    EXPECT_GT(time.seconds, 0.0);
}

TEST(Launch, ArgumentErrorsNameTheCallKernelAndStatus) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
    Buffer<unsigned> out(context, 16, "words");
    // A 64-bit value where the kernel takes a 32-bit uint.
    const std::string message =
        test::error_of([&] { context.launch(kernel, 16, uint64_t{5}, 6u, 7u, 1u, out); });
    EXPECT_NE(message.find("clSetKernelArg(rng_stream_words argument 2) failed: "
                           "CL_INVALID_ARG_SIZE"),
              std::string::npos)
        << message;
}

TEST(Launch, UnknownKernelNameIsReported) {
    const std::string message =
        test::error_of([] { test::shared_context().kernel("rng_probe.cl", "no_such_kernel"); });
    EXPECT_NE(message.find("clCreateKernel(no_such_kernel in rng_probe.cl) failed: "
                           "CL_INVALID_KERNEL_NAME"),
              std::string::npos)
        << message;
}

TEST(Launch, OversizedWorkGroupIsRefusedByName) {
    ContextOptions options = test::default_context_options();
    options.local_size = 1 << 20;
    Context context(options);
    Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
    Buffer<unsigned> out(context, 16, "words");
    const std::string message =
        test::error_of([&] { context.launch(kernel, 16, 1u, 2u, 3u, 1u, out); });
    EXPECT_NE(message.find("rng_stream_words"), std::string::npos) << message;
    EXPECT_NE(message.find("work-group size"), std::string::npos) << message;
}

TEST(Launch, BuffersBeyondTheDeviceLimitAreRefusedBeforeAllocation) {
    Context& context = test::shared_context();
    const uint64_t too_many = context.device().max_allocation / sizeof(float) + 1;
    const std::string message = test::error_of(
        [&] { Buffer<float> huge(context, static_cast<size_t>(too_many), "huge_film"); });
    EXPECT_NE(message.find("buffer 'huge_film'"), std::string::npos) << message;
    EXPECT_NE(message.find("largest allocation"), std::string::npos) << message;
}

}  // namespace
}  // namespace rc
