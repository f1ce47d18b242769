//! \file error.h
//! \brief Exception hierarchy of meshdiff. The library throws these and never
//! exits or prints; the CLI maps each class to a distinct exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace meshdiff {

//! Base class of every error meshdiff throws on purpose.
class Error : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

//! A file could not be opened, read, parsed or written (exit code 3).
class IoError : public Error
{
public:
    using Error::Error;
};

//! The input was read but is not a usable mesh: empty, no faces, NaN/Inf
//! coordinates, face indices out of range (exit code 4).
class InvalidMeshError : public Error
{
public:
    using Error::Error;
};

//! An option or argument is out of its domain (exit code 2, as usage errors).
class InvalidArgumentError : public Error
{
public:
    using Error::Error;
};

//! A numerical solve failed where no fallback exists (exit code 5).
class SolverError : public Error
{
public:
    using Error::Error;
};

//! The computation was stopped because its Progress (progress.h) said
//! cancelled(), e.g. on Ctrl-C (exit code 130, the shell's code for SIGINT).
class Cancelled : public Error
{
public:
    Cancelled() : Error("cancelled") {}
    using Error::Error;
};

}  // namespace meshdiff
