//! \file subprocess.h
//! \brief Running a child process with its output captured and a time limit,
//! so that a crash, an abort or a hang of one batch pair cannot stop the batch.
#pragma once

#include <string>
#include <vector>

namespace meshdiff::cli {

//! How a child process ended.
struct ChildResult
{
    int exit_code = -1;      //!< its exit code, or -1 if a signal ended it
    int signal = 0;          //!< the signal that ended it (0: none)
    bool timed_out = false;  //!< killed (SIGKILL) because the time limit passed
    bool stopped = false;    //!< sent SIGTERM because \p stop said so
    std::string out;         //!< everything it wrote to stdout
    std::string err;         //!< everything it wrote to stderr
};

//! Runs \p program with \p args (args[0] is the program's name for itself),
//! stdin from /dev/null, and waits for it; after \p timeout_seconds (0: no
//! limit) it is killed with SIGKILL. With \p stop, polled 10 times a second:
//! once it returns true the child is sent SIGTERM (to stop as on Ctrl-C), and
//! SIGKILL if it has not ended 5 s later.
//! \throw IoError if the process cannot be started.
ChildResult run_child(const std::string& program, const std::vector<std::string>& args, double timeout_seconds,
                      bool (*stop)() = nullptr);

//! The path of the running executable (/proc/self/exe).
std::string self_executable();

}  // namespace meshdiff::cli
