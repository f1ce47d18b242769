// The OBJ reader: "v x y z [...]" (a w or colour after x y z is ignored) and
// "f c1 c2 c3 [...]" with corners i, i/t, i//n or i/t/n, i counted from 1 or,
// if negative, back from the last vertex so far. '#' starts a comment. Every
// other statement (vt, vn, vp, g, o, s, usemtl, mtllib, curves, ...) is
// ignored; mtllib files are never opened. Line and point elements (l, p) are
// not surfaces: ignored too, but a file that has only them says so.
#include "io/readers/readers.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <limits>

namespace meshdiff::detail {

namespace {

// The vertex part of a face corner; false if the corner is not i, i/t, i//n or i/t/n.
bool parse_corner(std::string_view corner, std::int64_t& index)
{
    std::string_view parts[3];
    std::size_t n = 0;
    for (;;) {
        const auto slash = corner.find('/');
        if (n == 3) return false;
        parts[n++] = corner.substr(0, slash);
        if (slash == std::string_view::npos) break;
        corner.remove_prefix(slash + 1);
    }
    std::int64_t unused = 0;
    for (std::size_t k = 1; k < n; ++k)
        if (!parts[k].empty() && !parse_integer(parts[k], unused)) return false;
    return parse_integer(parts[0], index);
}

}  // namespace

Soup read_obj(const std::string& path)
{
    const std::string text = read_file(path);
    TextLines lines(text, '#');
    std::vector<std::string_view> tok;
    Soup soup;
    std::size_t non_surface = 0;
    while (lines.next_tokens(tok)) {
        const std::string_view kw = tok[0];
        if (kw == "v") {
            const std::size_t i = soup.points.size();
            if (tok.size() < 4)
                throw IoError(fmt::format("{}: line {}: vertex {} has {} numbers, expected x y z", path, lines.line(),
                                          i + 1, tok.size() - 1));
            const auto where = [&] { return fmt::format("{}: line {}: vertex {}", path, lines.line(), i + 1); };
            const double x = coordinate(tok[1], where), y = coordinate(tok[2], where), z = coordinate(tok[3], where);
            soup.points.emplace_back(x, y, z);
        } else if (kw == "f") {
            const auto n_so_far = std::int64_t(soup.points.size());
            std::vector<int> poly;
            poly.reserve(tok.size() - 1);
            for (std::size_t c = 1; c < tok.size(); ++c) {
                std::int64_t v = 0;
                if (!parse_corner(tok[c], v))
                    throw IoError(fmt::format("{}: line {}: {} is not a face corner (i, i/t, i//n or i/t/n)", path,
                                              lines.line(), quote(tok[c])));
                if (v == 0)
                    throw InvalidMeshError(fmt::format(
                        "{}: line {}: face corner {} has vertex index 0 (OBJ counts from 1)", path, lines.line(), c));
                const std::int64_t idx = v > 0 ? v - 1 : n_so_far + v;
                if (idx < 0)
                    throw InvalidMeshError(
                        fmt::format("{}: line {}: face corner {} refers to vertex {}, but only {} precede it", path,
                                    lines.line(), c, v, n_so_far));
                if (idx > std::numeric_limits<int>::max())
                    throw InvalidMeshError(
                        fmt::format("{}: line {}: face corner {} refers to vertex {}", path, lines.line(), c, v));
                poly.push_back(int(idx));
            }
            if (poly.size() < 3)
                throw InvalidMeshError(fmt::format("{}: line {}: face {} has {} corners", path, lines.line(),
                                                   soup.polygons.size(), poly.size()));
            soup.polygons.push_back(std::move(poly));
        } else if (kw == "l" || kw == "p") {
            ++non_surface;
        }
    }
    if (soup.polygons.empty() && non_surface > 0)
        throw InvalidMeshError(
            fmt::format("{}: mesh has no faces, only {} line and point elements (not surfaces)", path, non_surface));
    return soup;
}

}  // namespace meshdiff::detail
