// The OFF reader. Accepted: a first line [ST][C][N]OFF (texture coordinates,
// colours, normals after x y z: ignored), the counts "vertices faces [edges]"
// on the same line or the next one (also glued to the keyword, "OFF1234 ...",
// as ModelNet's files have them), '#' comments, one vertex per line (x y z,
// further numbers ignored), one face per line ("k i1 .. ik", further numbers,
// such as a colour, ignored). Refused: 4OFF and nOFF (homogeneous or
// n-dimensional coordinates), binary OFF, a file without the keyword, counts
// that the body does not match (truncated or trailing data).
#include "io/readers/readers.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <limits>

namespace meshdiff::detail {

namespace {

// The header keyword: true if \p kw is [ST][C][N]OFF; \p rest gets what follows
// "OFF" in the token (digits of a glued count).
bool parse_keyword(std::string_view kw, std::string_view& rest)
{
    const auto at = kw.find("OFF");
    if (at == std::string_view::npos) return false;
    std::string_view prefix = kw.substr(0, at);
    rest = kw.substr(at + 3);
    for (const std::string_view letters : {"ST", "C", "N"})
        if (prefix.substr(0, letters.size()) == letters) prefix.remove_prefix(letters.size());
    return prefix.empty();
}

std::uint64_t parse_count(const std::string& path, std::size_t line, std::string_view token, const char* what)
{
    std::int64_t n = 0;
    if (!parse_integer(token, n))
        throw IoError(fmt::format("{}: line {}: the {} count {} is not an integer", path, line, what, quote(token)));
    if (n < 0) throw IoError(fmt::format("{}: line {}: negative {} count {}", path, line, what, n));
    return std::uint64_t(n);
}

}  // namespace

Soup read_off(const std::string& path)
{
    const std::string text = read_file(path);
    TextLines lines(text, '#');
    std::vector<std::string_view> tok;
    if (!lines.next_tokens(tok)) throw IoError(fmt::format("{}: no OFF header (the file holds no data)", path));

    std::string_view rest;
    if (!parse_keyword(tok[0], rest)) {
        const bool variant = tok[0].find("OFF") != std::string_view::npos;
        throw IoError(fmt::format("{}: line {}: {} {}", path, lines.line(), quote(tok[0]),
                                  variant ? "is an OFF variant meshdiff does not read (4OFF and nOFF are not "
                                            "3D; accepted: [ST][C][N]OFF)"
                                          : "is not an OFF header (expected OFF, COFF, NOFF, STOFF, ...)"));
    }
    std::vector<std::string_view> counts;
    if (!rest.empty()) counts.push_back(rest);
    counts.insert(counts.end(), tok.begin() + 1, tok.end());
    if (!counts.empty() && counts[0] == "BINARY")
        throw IoError(fmt::format("{}: binary OFF is not supported (write it as ASCII OFF or PLY)", path));
    if (counts.empty()) {
        if (!lines.next_tokens(tok)) throw IoError(fmt::format("{}: the OFF header has no counts line", path));
        counts = tok;
    }
    if (counts.size() < 2 || counts.size() > 3)
        throw IoError(fmt::format("{}: line {}: expected the counts 'vertices faces edges', got {} numbers", path,
                                  lines.line(), counts.size()));
    const std::uint64_t nv = parse_count(path, lines.line(), counts[0], "vertex");
    const std::uint64_t nf = parse_count(path, lines.line(), counts[1], "face");
    if (counts.size() == 3) parse_count(path, lines.line(), counts[2], "edge");  // checked, not used

    // A vertex line is at least "0 0 0\n" (6 bytes), a face line "3 0 1 2\n" (8).
    check_count(path, nv, 6, lines.bytes_left(), "vertices");
    check_count(path, nf, 8, lines.bytes_left() > 6 * nv ? lines.bytes_left() - 6 * nv : 0, "faces");
    if (nv > std::uint64_t(std::numeric_limits<int>::max()))
        throw IoError(fmt::format("{}: {} vertices are more than meshdiff can index", path, nv));

    Soup soup;
    soup.points.reserve(nv);
    for (std::uint64_t i = 0; i < nv; ++i) {
        if (!lines.next_tokens(tok))
            throw IoError(
                fmt::format("{}: the file ends after {} of the {} vertices the header declares", path, i, nv));
        if (tok.size() < 3)
            throw IoError(fmt::format("{}: line {}: vertex {} has {} numbers, expected x y z", path, lines.line(), i,
                                      tok.size()));
        const auto where = [&] { return fmt::format("{}: line {}: vertex {}", path, lines.line(), i); };
        const double x = coordinate(tok[0], where), y = coordinate(tok[1], where), z = coordinate(tok[2], where);
        soup.points.emplace_back(x, y, z);
    }

    soup.polygons.reserve(nf);
    for (std::uint64_t f = 0; f < nf; ++f) {
        if (!lines.next_tokens(tok))
            throw IoError(fmt::format("{}: the file ends after {} of the {} faces the header declares", path, f, nf));
        std::int64_t k = 0;
        if (!parse_integer(tok[0], k))
            throw IoError(fmt::format("{}: line {}: face {}: the corner count {} is not an integer", path, lines.line(),
                                      f, quote(tok[0])));
        if (k < 0)
            throw IoError(fmt::format("{}: line {}: face {} has a negative corner count {}", path, lines.line(), f, k));
        if (std::uint64_t(k) > tok.size() - 1)
            throw IoError(fmt::format("{}: line {}: face {} declares {} corners but lists {} numbers", path,
                                      lines.line(), f, k, tok.size() - 1));
        std::vector<int> poly(static_cast<std::size_t>(k));
        for (std::size_t c = 0; c < poly.size(); ++c) {
            std::int64_t v = 0;
            if (!parse_integer(tok[c + 1], v))
                throw IoError(fmt::format("{}: line {}: face {}: the vertex index {} is not an integer", path,
                                          lines.line(), f, quote(tok[c + 1])));
            if (v < 0 || v >= std::int64_t(nv))
                throw InvalidMeshError(
                    fmt::format("{}: line {}: face {} refers to vertex {}, but there are {} vertices", path,
                                lines.line(), f, v, nv));
            poly[c] = int(v);
        }
        soup.polygons.push_back(std::move(poly));
    }
    if (lines.next_tokens(tok))
        throw IoError(fmt::format("{}: line {}: data after the {} faces the header declares ({}; a wrong count?)", path,
                                  lines.line(), nf, quote(tok[0])));
    return soup;
}

}  // namespace meshdiff::detail
