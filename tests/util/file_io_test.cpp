// host/util's defences against hostile files: reads of regular files only, within a
// size limit; the output batch that commits a run's files together or not at all; values quoted
// short in error lines; a library's stderr captured into the error line.
#include "util/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "error_of.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_checksum.h"
#include "util/stderr_capture.h"
#include "util/text.h"

namespace rc {
namespace {

TEST(FileIo, ReadsOnlyRegularFilesWithinTheLimit) {
    const auto dir = test::scratch_dir("file_io_read");
    std::ofstream(dir / "ten.txt") << "0123456789";
    EXPECT_EQ(read_file(dir / "ten.txt", 10), "0123456789");
    EXPECT_NE(test::error_of([&] {
                  read_file(dir / "ten.txt", 9, "mesh file");
              }).find("ten.txt (mesh file): 10 bytes, more than the limit of 9"),
              std::string::npos);
    EXPECT_NE(test::error_of([&] { read_file(dir); }).find("not a regular file"),
              std::string::npos);
    EXPECT_NE(test::error_of([] { read_file("/dev/zero"); }).find("/dev/zero: not a regular file"),
              std::string::npos);
    // A FIFO with no writer: refused at once, never waited on.
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    EXPECT_NE(test::error_of([&] { read_file(dir / "fifo"); }).find("not a regular file"),
              std::string::npos);
    EXPECT_NE(test::error_of([&] { read_file(dir / "absent"); }).find("cannot open file"),
              std::string::npos);
}

TEST(FileIo, AnOutputBatchCommitsEveryFileAtTheEndOrNone) {
    const auto dir = test::scratch_dir("file_io_batch");
    std::ofstream(dir / "old.txt") << "old";
    {
        OutputBatch batch;
        write_file_atomically(dir / "old.txt", "new");
        write_file_atomically(dir / "fresh.txt", "first");
        write_file_atomically(dir / "fresh.txt", "second");  // a path written twice: the last
        write_file_atomically(dir / "cache.bin", "now", WriteTiming::kNow);
        // Nothing has reached its path but what was written at once; the rest is staged.
        EXPECT_EQ(read_file(dir / "old.txt"), "old");
        EXPECT_FALSE(std::filesystem::exists(dir / "fresh.txt"));
        EXPECT_EQ(read_file(dir / "cache.bin"), "now");
        EXPECT_EQ(test::file_names(dir).size(), 4u);  // old, cache and two staged temporaries
        batch.commit();
    }
    EXPECT_EQ(read_file(dir / "old.txt"), "new");
    EXPECT_EQ(read_file(dir / "fresh.txt"), "second");
    EXPECT_EQ(test::file_names(dir),
              (std::vector<std::string>{"cache.bin", "fresh.txt", "old.txt"}));

    // A batch that ends without its commit (a failed run) removes what it staged.
    {
        OutputBatch batch;
        write_file_atomically(dir / "old.txt", "lost");
        write_file_atomically(dir / "other.txt", "lost");
    }
    EXPECT_EQ(read_file(dir / "old.txt"), "new");
    EXPECT_EQ(test::file_names(dir),
              (std::vector<std::string>{"cache.bin", "fresh.txt", "old.txt"}));
    // Without a batch a write reaches its path at once.
    write_file_atomically(dir / "other.txt", "at once");
    EXPECT_EQ(read_file(dir / "other.txt"), "at once");
}

TEST(FileIo, OutputsThatCannotBeFilesAreRefusedBeforeTheWork) {
    const auto dir = test::scratch_dir("file_io_outputs");
    std::filesystem::create_directories(dir / "stats.json");
    const std::string directory =
        test::error_of([&] { check_writable_parent(dir / "stats.json", "--stats"); });
    EXPECT_NE(directory.find("--stats"), std::string::npos) << directory;
    EXPECT_NE(directory.find("is a directory"), std::string::npos) << directory;
    EXPECT_NE(test::error_of([] {
                  check_writable_parent("/dev/null", "--stats");
              }).find("exists and is not a regular file"),
              std::string::npos);
    EXPECT_NE(test::error_of([&] {
                  check_writable_parent(dir / "missing/x.json", "--json");
              }).find("does not exist or is not writable"),
              std::string::npos);
    EXPECT_EQ(test::error_of([&] { check_writable_parent(dir / "new.json", "--json"); }), "");
    try {
        check_writable_parent(dir / "stats.json", "--stats");
    } catch (const Error& error) {
        EXPECT_EQ(error.exit_code(), kExitUsage);
    }
}

TEST(FileIo, TheTrailingChecksumCatchesAnyChangedByteAndATruncation) {
    const std::string data = "radcache cache file \x01\x02 payload";
    std::string bytes = data;
    append_checksum(bytes);
    ASSERT_EQ(bytes.size(), data.size() + 8);
    EXPECT_EQ(bytes.substr(0, data.size()), data);
    EXPECT_TRUE(has_valid_checksum(bytes));
    for (size_t i = 0; i < bytes.size(); ++i) {  // the data's bytes and the checksum's own
        std::string changed = bytes;
        changed[i] = static_cast<char>(changed[i] ^ 0x10);
        EXPECT_FALSE(has_valid_checksum(changed)) << "byte " << i;
    }
    EXPECT_FALSE(has_valid_checksum(bytes.substr(0, bytes.size() - 1)));
    EXPECT_FALSE(has_valid_checksum(bytes.substr(1)));
    EXPECT_FALSE(has_valid_checksum("1234567"));  // shorter than a checksum
    std::string empty;
    append_checksum(empty);
    EXPECT_TRUE(has_valid_checksum(empty));
}

TEST(Text, ExcerptsAreShortAndOnOneLine) {
    EXPECT_EQ(excerpt("short"), "short");
    EXPECT_EQ(excerpt("a\nb\tc\x1b[31m"), "a\\nb\\tc\\x1b[31m");
    // UTF-8 kept whole; a byte that is not part of a well-formed sequence escaped (a Latin-1
    // é, a lone continuation byte, an overlong form, a surrogate, a cut sequence).
    EXPECT_EQ(excerpt("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"),
              "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
    EXPECT_EQ(excerpt("caf\xe9"), "caf\\xe9");
    EXPECT_EQ(excerpt("\x80|\xc0\xaf|\xed\xa0\x80|\xe2\x82"),
              "\\x80|\\xc0\\xaf|\\xed\\xa0\\x80|\\xe2\\x82");
    const std::string long_text(5000000, 'x');
    const std::string cut = excerpt(long_text);
    EXPECT_EQ(cut, std::string(80, 'x') + "... (5000000 bytes)");
    EXPECT_EQ(excerpt(std::string(80, 'y')), std::string(80, 'y'));
}

TEST(StderrCapture, CapturesWhatALibraryPrints) {
    StderrCapture capture;
    std::fprintf(stderr, "libpng error: IDAT: CRC error\n");
    std::fprintf(stderr, "second line\n");
    EXPECT_EQ(capture.finish(), "libpng error: IDAT: CRC error; second line");
    EXPECT_EQ(capture.finish(), "");  // already restored
}

}  // namespace
}  // namespace rc
