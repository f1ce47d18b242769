#include "meshdiff/io/output_file.h"

#include "meshdiff/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <system_error>

namespace meshdiff {

namespace {

std::filesystem::path temporary_for(const std::filesystem::path& path)
{
    static std::atomic<unsigned> counter{0};
    const std::string name =
        fmt::format(".{}.meshdiff-{}-{}{}", path.stem().string(), ::getpid(), counter++, path.extension().string());
    return path.has_parent_path() ? path.parent_path() / name : std::filesystem::path(name);
}

thread_local StagedOutputs* current_stage = nullptr;

void rename_onto(const std::filesystem::path& tmp, const std::filesystem::path& path)
{
    std::error_code ec, ignored;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ignored);
        throw IoError(fmt::format("{}: cannot write ({})", path.string(), ec.message()));
    }
}

}  // namespace

StagedOutputs::StagedOutputs() : previous_(current_stage)
{
    current_stage = this;
}

StagedOutputs::~StagedOutputs()
{
    current_stage = previous_;
    std::error_code ignored;
    for (const auto& [tmp, target] : staged_) std::filesystem::remove(tmp, ignored);
}

void StagedOutputs::commit()
{
    auto staged = std::move(staged_);
    staged_.clear();
    for (std::size_t i = 0; i < staged.size(); ++i) {
        try {
            rename_onto(staged[i].first, staged[i].second);
        } catch (...) {
            std::error_code ignored;
            for (std::size_t j = i + 1; j < staged.size(); ++j) std::filesystem::remove(staged[j].first, ignored);
            throw;
        }
    }
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write)
{
    // A device, a pipe or a socket (/dev/null, /dev/stdout, a FIFO), also
    // through a symbolic link, is written in place: there is no file to
    // replace, and a rename would put a regular file in its stead (as root,
    // even over /dev/null).
    std::error_code status_ec;
    const std::filesystem::file_status st = std::filesystem::status(path, status_ec);
    if (!status_ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) &&
        !std::filesystem::is_directory(st)) {
        write(path);
        return;
    }
    const std::filesystem::path tmp = temporary_for(path);
    std::error_code ignored;
    try {
        write(tmp);
    } catch (...) {
        std::filesystem::remove(tmp, ignored);
        throw;
    }
    if (current_stage) {
        current_stage->staged_.emplace_back(tmp, path);
        return;
    }
    rename_onto(tmp, path);
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b)
{
    std::error_code ec;
    const bool same = std::filesystem::equivalent(a, b, ec);
    return !ec && same;
}

void refuse_overwriting_inputs(const std::string& what, const std::string& output,
                               const std::vector<std::string>& inputs)
{
    if (output.empty() || output == "-") return;
    for (const auto& in : inputs)
        if (same_file(output, in))
            throw OptionError(
                what, fmt::format("'{}' is the input file '{}'; meshdiff does not overwrite its inputs", output, in));
}

}  // namespace meshdiff
