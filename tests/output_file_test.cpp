#include "meshdiff/io/output_file.h"

#include "meshdiff/error.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

using namespace meshdiff;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name)
{
    const fs::path d = fs::temp_directory_path() / ("meshdiff_output_file_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

void write_text(const fs::path& p, const std::string& text)
{
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + p.string());
}

std::string read_text(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(OutputFile, ReplacesARegularFileThroughATemporaryOne)
{
    const fs::path d = fresh_dir("regular");
    const fs::path out = d / "report.json";
    write_text(out, "old");
    fs::path used;
    write_atomically(out, [&](const fs::path& tmp) {
        used = tmp;
        EXPECT_NE(tmp, out);
        EXPECT_EQ(tmp.parent_path(), out.parent_path());
        EXPECT_EQ(tmp.extension(), ".json");
        EXPECT_EQ(read_text(out), "old");  // untouched until the rename
        write_text(tmp, "new");
    });
    EXPECT_EQ(read_text(out), "new");
    EXPECT_FALSE(fs::exists(used));
    fs::remove_all(d);
}

TEST(OutputFile, AFailedWriteLeavesTheOldFileAndNoTemporary)
{
    const fs::path d = fresh_dir("failed");
    const fs::path out = d / "report.json";
    write_text(out, "old");
    EXPECT_THROW(write_atomically(out,
                                  [&](const fs::path& tmp) {
                                      write_text(tmp, "half");
                                      throw IoError("disk full");
                                  }),
                 IoError);
    EXPECT_EQ(read_text(out), "old");
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(d)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u);
    fs::remove_all(d);
}

TEST(OutputFile, ADeviceIsWrittenInPlaceNotReplaced)
{
    // A copy of /dev/null in a folder of our own (mknod needs root; as root a
    // rename onto the real /dev/null would replace the device with a file).
    if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
    const fs::path d = fresh_dir("device");
    const fs::path null = d / "null";
    ASSERT_EQ(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
    fs::path used;
    write_atomically(null, [&](const fs::path& p) {
        used = p;
        write_text(p, "{}");
    });
    EXPECT_EQ(used, null);
    EXPECT_TRUE(fs::is_character_file(null));
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(d)) entries += bool(e.path().filename().string().size());
    EXPECT_EQ(entries, 1u);  // no temporary left
    fs::remove_all(d);
}

// The text waiting in a FIFO's read end, opened without blocking before the
// write; "" if the FIFO was replaced (its old read end then gets nothing).
std::string drain(int fd)
{
    std::string text;
    char buf[256];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n <= 0) break;
        text.append(buf, std::size_t(n));
    }
    return text;
}

TEST(OutputFile, AFifoIsWrittenInPlace)
{
    const fs::path d = fresh_dir("fifo");
    const fs::path fifo = d / "pipe.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    write_atomically(fifo, [&](const fs::path& p) { write_text(p, "through the pipe"); });
    EXPECT_EQ(drain(fd), "through the pipe");
    ::close(fd);
    EXPECT_TRUE(fs::is_fifo(fifo));
    // Through a symbolic link too: the link and the FIFO stay.
    const fs::path link = d / "link.json";
    fs::create_symlink(fifo, link);
    fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    write_atomically(link, [&](const fs::path& p) { write_text(p, "via the link"); });
    EXPECT_EQ(drain(fd), "via the link");
    ::close(fd);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_fifo(fifo));
    fs::remove_all(d);
}
