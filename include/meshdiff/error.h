//! \file error.h
//! \brief Exception hierarchy of meshdiff. The library throws these and never
//! exits or prints; the CLI maps each class to a distinct exit code.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

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

//! An option of the library's options structs (ProfileOptions, CompareOptions,
//! ...) outside its domain or in a combination that is refused; field() names
//! it as a path in those structs ("levels", "sampling.samples",
//! "hausdorff.relative_tolerance": docs/library.md lists them), problem() says
//! what is wrong without naming it. what() is "field: problem". The front ends
//! (CLI, batch, Python) word the message with their own spelling of the field
//! (`--samples`, `samples=`), so every rule and limit lives in one place.
class OptionError : public InvalidArgumentError
{
public:
    OptionError(std::string field, std::string problem)
        : InvalidArgumentError(field + ": " + problem), field_(std::move(field)), problem_(std::move(problem))
    {}
    const std::string& field() const noexcept { return field_; }
    const std::string& problem() const noexcept { return problem_; }

private:
    std::string field_;
    std::string problem_;
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
