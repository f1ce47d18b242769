//! \file output_file.h
//! \brief Writing output files so that nothing is torn or destroyed: every
//! file meshdiff writes goes to a temporary file in the same folder, which is
//! renamed onto the final name only once it is complete. A run that is killed
//! or fails leaves either the old file or the complete new one (rename is
//! atomic within a file system on POSIX).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff {

//! Calls \p write with a temporary path in the folder of \p path (named
//! `.<stem>.meshdiff-<pid>-<n><extension>`, so a writer that picks the format
//! by extension sees the right one), then renames it onto \p path. If \p write
//! throws, or the rename fails, the temporary file is removed and \p path is
//! left as it was. An existing \p path that is neither a regular file nor a
//! folder (a device such as /dev/null, a FIFO, a socket; also through a
//! symbolic link) is passed to \p write itself: it is written in place, never
//! replaced.
//! \throw IoError if the rename fails; whatever \p write throws.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

//! Stages every write_atomically() made on this thread while it lives: the
//! temporary file is written as usual, but renamed onto its target only by
//! commit(). Destroyed without commit() (an exception on the way), it removes
//! the temporaries it holds, so a run that fails leaves none of its outputs,
//! not only none torn. Scopes nest: an inner one stages into itself.
//! (Targets that are not regular files, such as /dev/null, are written at once.)
class StagedOutputs
{
public:
    StagedOutputs();
    ~StagedOutputs();
    StagedOutputs(const StagedOutputs&) = delete;
    StagedOutputs& operator=(const StagedOutputs&) = delete;

    //! Renames every staged file onto its target, in the order written.
    //! \throw IoError if a rename fails (the files not yet renamed are removed).
    void commit();

private:
    friend void write_atomically(const std::filesystem::path&,
                                 const std::function<void(const std::filesystem::path&)>&);
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // temporary, target
    StagedOutputs* previous_;
};

//! True if \p a and \p b are the same existing file, also through symbolic or
//! hard links (std::filesystem::equivalent); false if either does not exist.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

//! Refuses to write the output \p output of \p what (e.g. "--json", or an
//! options field such as "outputs.json") onto one of \p inputs: the same
//! file, also through links; "" and "-" (standard output) are no file.
//! \throw OptionError(\p what) naming both.
void refuse_overwriting_inputs(const std::string& what, const std::string& output,
                               const std::vector<std::string>& inputs);

}  // namespace meshdiff
