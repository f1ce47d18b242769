//! \file cli.h
//! \brief The meshdiff command-line tool: argument parsing and dispatch. Kept
//! apart from main() so that it can be driven from tests.
#pragma once

#include <string>
#include <vector>

namespace meshdiff::cli {

//! Exit codes, documented in the README.
enum ExitCode : int
{
    kOk = 0,
    kUsage = 2,         //!< bad command line or option value
    kIoError = 3,       //!< a file could not be read or written
    kInvalidMesh = 4,   //!< the file was read but is not a usable mesh
    kSolverError = 5,   //!< a numerical step failed
    kInternal = 70,     //!< a bug: please report
    kBatchFailures = 6  //!< batch finished, but some pairs failed
};

//! Runs the tool on argv-style arguments (args[0] is the program name).
int run(const std::vector<std::string>& args);

}  // namespace meshdiff::cli
