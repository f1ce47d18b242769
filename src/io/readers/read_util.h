// Private: what meshdiff's own mesh readers (ply_reader, off_reader,
// obj_reader, stl_reader) share: the raw vertex and polygon lists they
// return, quoting file contents in one-line error messages, strict number
// parsing and the check of a header count against the bytes left.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"

#include "io/readers/polygon_list.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace meshdiff::detail {

//! A file's vertices and polygons as the file lists them (indices 0-based,
//! not yet checked against the vertex count).
struct Soup
{
    std::vector<Vec3> points;
    PolygonList polygons;
};

//! \p text for an error message: in single quotes, at most \p max_bytes of it
//! (then "..."), every byte outside printable ASCII (and the backslash) written
//! as \xNN, so that the message stays one line of plain text.
std::string quote(std::string_view text, std::size_t max_bytes = 40);

//! The whole file. \throw IoError naming \p path if it cannot be read.
std::string read_file(const std::string& path);

//! Lines of a text buffer with their numbers (1-based); "\r\n" and "\n" end a
//! line. Tokens are separated by spaces, tabs and other ASCII white space.
class TextLines
{
public:
    explicit TextLines(std::string_view text, char comment = '\0') : text_(text), comment_(comment) {}

    //! The next line holding a token (after cutting a comment off, if the
    //! format has comments), split into \p tokens; false at the end.
    bool next_tokens(std::vector<std::string_view>& tokens);
    //! The number of the line next_tokens() returned last.
    std::size_t line() const { return line_; }
    //! Bytes after that line.
    std::size_t bytes_left() const { return text_.size() - pos_; }

private:
    std::string_view text_;
    char comment_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
};

//! Splits \p line at white space.
void split(std::string_view line, std::vector<std::string_view>& tokens);

//! How a text token parsed as a number.
enum class Number
{
    Ok,         //!< a finite value
    NotFinite,  //!< "nan", "inf" and the like
    Overflow,   //!< beyond the range of a double (e.g. 1e400)
    Invalid     //!< not a number, or not only a number
};

//! Parses a decimal real (the whole token; a leading '+' allowed; C locale).
//! A value too small for a double is 0 or subnormal, as strtod gives it.
Number parse_double(std::string_view token, double& value);

//! Parses a coordinate of a format that OpenMesh read in float precision
//! (OBJ, OFF, ASCII STL): the token rounded once to float, as OpenMesh's
//! `stream >> float` did, so that results on such files stay the same. A value
//! beyond float range but within double range is returned unrounded (to be
//! caught by the coordinate limit of io.h with its real value).
Number parse_float_coordinate(std::string_view token, double& value);

//! A coordinate of a float-precision format (parse_float_coordinate()).
//! \p where() names the place for the message ("a.off: line 4: vertex 1").
//! \throw IoError if \p token is not a number
//! \throw InvalidMeshError if it is NaN, Inf, overflows a double or lies
//!        beyond max_coordinate (io.h).
template <class Where>
double coordinate(std::string_view token, const Where& where)
{
    double v = 0.0;
    switch (parse_float_coordinate(token, v)) {
        case Number::Ok:
            break;
        case Number::Invalid:
            throw IoError(fmt::format("{}: {} is not a number", where(), quote(token)));
        case Number::NotFinite:
            throw InvalidMeshError(fmt::format("{} has a non-finite coordinate {}", where(), quote(token)));
        case Number::Overflow:
            throw InvalidMeshError(
                fmt::format("{} has a non-finite coordinate {} (beyond double range)", where(), quote(token)));
    }
    if (std::abs(v) > max_coordinate)
        throw InvalidMeshError(fmt::format("{} has the coordinate {} beyond meshdiff's limit of +-{}", where(),
                                           quote(token), max_coordinate));
    return v;
}

//! Parses a decimal integer (the whole token; a leading '+' allowed). A value
//! beyond 64 bits is clamped to the nearest 64-bit limit.
bool parse_integer(std::string_view token, std::int64_t& value);

//! \throw IoError if \p count items of at least \p min_bytes each cannot fit in
//! the \p bytes_left bytes of the file after its header: checked before
//! anything is allocated or looped over from a header count.
void check_count(const std::string& path, std::uint64_t count, std::uint64_t min_bytes, std::uint64_t bytes_left,
                 std::string_view what);

}  // namespace meshdiff::detail
