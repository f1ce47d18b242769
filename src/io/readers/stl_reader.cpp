// The STL reader. Binary when the file is exactly 84 + 50 n bytes for the
// triangle count n at byte 80 (OpenMesh's test), else ASCII when it starts
// with "solid" and looks like text: solid/facet normal/outer loop/vertex x3/
// endloop/endfacet/endsolid, keywords in any case, several solids in a row
// allowed. Anything else (a binary count that does not match the size, data
// after the last endsolid, a file ending inside a solid) is an IoError.
//
// Corners are merged into vertices as OpenMesh's STL reader merged them: a
// std::map over float positions whose comparator treats coordinates that
// differ by at most FLT_MIN as equal (so exact equality, with -0 = +0 and
// subnormals near each other merged), the first position seen kept, vertices
// numbered in order of first appearance. Facets whose corners merge are kept
// and reach io.cpp, which drops and counts them (OpenMesh dropped them
// silently). Coordinates are checked before merging: a NaN would break the
// map's ordering.
#include "io/readers/readers.h"

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"

#include <fmt/format.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <map>

namespace meshdiff::detail {

namespace {

using Key = std::array<float, 3>;

// OpenMesh's CmpVec with its default epsilon FLT_MIN, in float arithmetic.
struct CmpVec
{
    bool operator()(const Key& a, const Key& b) const
    {
        constexpr float eps = FLT_MIN;
        if (std::fabs(a[0] - b[0]) <= eps) {
            if (std::fabs(a[1] - b[1]) <= eps) return a[2] < b[2] - eps;
            return a[1] < b[1] - eps;
        }
        return a[0] < b[0] - eps;
    }
};

class Welder
{
public:
    explicit Welder(Soup& soup) : soup_(soup) {}
    int vertex(const Key& p)
    {
        const auto it = map_.find(p);
        if (it != map_.end()) return it->second;
        const int v = int(soup_.points.size());
        soup_.points.emplace_back(double(p[0]), double(p[1]), double(p[2]));
        map_.emplace(p, v);
        return v;
    }

private:
    Soup& soup_;
    std::map<Key, int, CmpVec> map_;
};

std::uint32_t le32(const unsigned char* b)
{
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

bool iequals(std::string_view a, std::string_view b)
{
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

// An ASCII STL's first token is "solid", and its start holds no control bytes.
bool looks_ascii(const std::string& text)
{
    const std::size_t head = std::min<std::size_t>(text.size(), 1024);
    for (std::size_t i = 0; i < head; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\v' && c != '\f') return false;
    }
    std::vector<std::string_view> tok;
    TextLines lines(text);
    return lines.next_tokens(tok) && iequals(tok[0], "solid");
}

// A corner must be finite and within the coordinate limit before it is merged:
// a NaN would break the map's ordering, a value beyond float range its key.
template <class Where>
void check_corner(const double* xyz, const Where& where)
{
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(xyz[k]))
            throw InvalidMeshError(
                fmt::format("{} has a non-finite coordinate ({}, {}, {})", where(), xyz[0], xyz[1], xyz[2]));
        if (std::fabs(xyz[k]) > max_coordinate)
            throw InvalidMeshError(fmt::format("{} has the coordinate {} beyond meshdiff's limit of +-{}", where(),
                                               xyz[k], max_coordinate));
    }
}

Soup read_binary(const std::string& path, const std::string& text, std::size_t n)
{
    Soup soup;
    Welder weld(soup);
    soup.polygons.reserve(n);
    const auto* b = reinterpret_cast<const unsigned char*>(text.data()) + 84;
    for (std::size_t t = 0; t < n; ++t, b += 50) {
        std::vector<int> tri(3);
        for (int c = 0; c < 3; ++c) {
            Key p;
            double xyz[3];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t bits = le32(b + 12 + 12 * c + 4 * k);
                std::memcpy(&p[std::size_t(k)], &bits, 4);
                xyz[k] = double(p[std::size_t(k)]);
            }
            check_corner(xyz, [&] { return fmt::format("{}: facet {} corner {}", path, t, c); });
            tri[std::size_t(c)] = weld.vertex(p);
        }
        soup.polygons.push_back(std::move(tri));
    }
    return soup;
}

// Tokens of an ASCII STL across lines.
class Tokens
{
public:
    Tokens(const std::string& path, const std::string& text) : path_(path), lines_(text) {}

    bool next(std::string_view& t)
    {
        while (at_ >= tok_.size()) {
            if (!lines_.next_tokens(tok_)) return false;
            at_ = 0;
        }
        t = tok_[at_++];
        return true;
    }
    std::string_view need(const char* what)
    {
        std::string_view t;
        if (!next(t)) throw IoError(fmt::format("{}: the file ends where {} should follow (truncated?)", path_, what));
        return t;
    }
    void keyword(const char* kw)
    {
        const std::string_view t = need(kw);
        if (!iequals(t, kw))
            throw IoError(fmt::format("{}: line {}: expected '{}', got {}", path_, lines_.line(), kw, quote(t)));
    }
    void skip_line() { at_ = tok_.size(); }
    std::size_t line() const { return lines_.line(); }

private:
    const std::string& path_;
    TextLines lines_;
    std::vector<std::string_view> tok_;
    std::size_t at_ = 0;
};

Soup read_ascii(const std::string& path, const std::string& text)
{
    Soup soup;
    Welder weld(soup);
    Tokens in(path, text);
    in.keyword("solid");
    in.skip_line();  // the solid's name
    for (;;) {
        std::string_view t = in.need("'facet' or 'endsolid'");
        if (iequals(t, "endsolid")) {
            in.skip_line();
            if (!in.next(t)) break;
            if (!iequals(t, "solid"))
                throw IoError(fmt::format("{}: line {}: data after 'endsolid': {}", path, in.line(), quote(t)));
            in.skip_line();
            continue;
        }
        if (!iequals(t, "facet"))
            throw IoError(
                fmt::format("{}: line {}: expected 'facet' or 'endsolid', got {}", path, in.line(), quote(t)));
        const std::size_t facet = soup.polygons.size();
        in.keyword("normal");
        for (int k = 0; k < 3; ++k) in.need("a normal");  // ignored (exporters write nan for degenerate facets)
        in.keyword("outer");
        in.keyword("loop");
        std::vector<int> tri(3);
        for (int c = 0; c < 3; ++c) {
            in.keyword("vertex");
            const auto where = [&] {
                return fmt::format("{}: line {}: facet {} corner {}", path, in.line(), facet, c);
            };
            double xyz[3];
            for (double& x : xyz) x = coordinate(in.need("a coordinate"), where);
            check_corner(xyz, where);
            tri[std::size_t(c)] = weld.vertex(Key{float(xyz[0]), float(xyz[1]), float(xyz[2])});
        }
        in.keyword("endloop");
        in.keyword("endfacet");
        soup.polygons.push_back(std::move(tri));
    }
    return soup;
}

}  // namespace

Soup read_stl(const std::string& path)
{
    const std::string text = read_file(path);
    if (text.size() >= 84) {
        const std::uint64_t n = le32(reinterpret_cast<const unsigned char*>(text.data()) + 80);
        if (84 + 50 * n == text.size()) return read_binary(path, text, std::size_t(n));
        if (!looks_ascii(text))
            throw IoError(
                fmt::format("{}: binary STL declares {} triangles ({} bytes) but the file has {} bytes "
                            "(truncated, or data after the triangles)",
                            path, n, 84 + 50 * n, text.size()));
    } else if (!looks_ascii(text)) {
        throw IoError(fmt::format("{}: not an STL file (too short for binary STL, and no ASCII 'solid')", path));
    }
    return read_ascii(path, text);
}

}  // namespace meshdiff::detail
