//! \file cli.h
//! \brief The meshdiff command-line tool: argument parsing and dispatch. Kept
//! apart from main() so that it can be driven from tests.
#pragma once

#include <exception>
#include <string>
#include <vector>

namespace meshdiff::cli {

//! Exit codes, documented in the README.
enum ExitCode : int
{
    kOk = 0,
    kUsage = 2,          //!< bad command line or option value
    kIoError = 3,        //!< a file could not be read or written
    kInvalidMesh = 4,    //!< the file was read but is not a usable mesh
    kSolverError = 5,    //!< a numerical step failed
    kInternal = 70,      //!< a bug: please report
    kBatchFailures = 6,  //!< batch finished, but some pairs failed
    kOutOfMemory = 7,    //!< memory ran out (a mesh or an option too large for this machine)
    kInterrupted = 130   //!< stopped by SIGINT (Ctrl-C) or SIGTERM; no output written (128 + SIGINT)
};

//! How a command that threw \p e ends: its exit code and its one-line message
//! (without the "meshdiff: " prefix). The one mapping from meshdiff's error
//! classes (error.h) to exit codes, used by every command and by batch for
//! each pair.
struct Failure
{
    int code;
    std::string message;
};
Failure failure_of(const std::exception& e);

//! Runs the tool on argv-style arguments (args[0] is the program name).
int run(const std::vector<std::string>& args);

//! The arguments of the running run(), as a shell would take them back
//! (quoted where needed), for the reports that show how they were made.
const std::string& command_line();

}  // namespace meshdiff::cli
