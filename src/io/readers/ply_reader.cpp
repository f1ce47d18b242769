#include "io/readers/ply_reader.h"

#include "meshdiff/error.h"

#include "io/readers/read_util.h"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <utility>

#ifndef MAP_POPULATE
#define MAP_POPULATE 0  // Linux's: the pages read ahead at once; elsewhere faulted in as read
#endif

namespace meshdiff::detail {

namespace {

enum class Type
{
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Float32,
    Float64
};

bool parse_type(const std::string& s, Type& t)
{
    static const std::pair<const char*, Type> names[] = {
        {"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
        {"short", Type::Int16},   {"int16", Type::Int16},     {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
        {"int", Type::Int32},     {"int32", Type::Int32},     {"uint", Type::UInt32},    {"uint32", Type::UInt32},
        {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
    for (const auto& [name, type] : names)
        if (s == name) {
            t = type;
            return true;
        }
    return false;
}

std::size_t type_size(Type t)
{
    switch (t) {
        case Type::Int8:
        case Type::UInt8:
            return 1;
        case Type::Int16:
        case Type::UInt16:
            return 2;
        case Type::Int32:
        case Type::UInt32:
        case Type::Float32:
            return 4;
        case Type::Float64:
            return 8;
    }
    return 0;
}

struct Property
{
    std::string name;
    Type type = Type::Float32;
    bool is_list = false;
    Type count_type = Type::UInt8;
};

struct Element
{
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> props;
};

const bool kHostLittleEndian = [] {
    const std::uint16_t one = 1;
    unsigned char c;
    std::memcpy(&c, &one, 1);
    return c == 1;
}();

enum class Format
{
    Ascii,
    BinaryLE,
    BinaryBE
};

// A binary value of type t at buf, little- or big-endian, as a double.
inline double decode(Type t, const unsigned char* buf, bool little)
{
    if (little && kHostLittleEndian) {
        switch (t) {
            case Type::Float32: {
                float f;
                std::memcpy(&f, buf, 4);
                return double(f);
            }
            case Type::Float64: {
                double d;
                std::memcpy(&d, buf, 8);
                return d;
            }
            case Type::Int32: {
                std::int32_t i;
                std::memcpy(&i, buf, 4);
                return double(i);
            }
            case Type::UInt8:
                return double(buf[0]);
            default:
                break;
        }
    }
    const std::size_t n = type_size(t);
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < n; ++i) bits |= std::uint64_t(buf[little ? i : n - 1 - i]) << (8 * i);
    switch (t) {
        case Type::Int8:
            return double(std::int8_t(bits));
        case Type::UInt8:
            return double(std::uint8_t(bits));
        case Type::Int16:
            return double(std::int16_t(bits));
        case Type::UInt16:
            return double(std::uint16_t(bits));
        case Type::Int32:
            return double(std::int32_t(bits));
        case Type::UInt32:
            return double(std::uint32_t(bits));
        case Type::Float32: {
            const auto b32 = std::uint32_t(bits);
            float f;
            std::memcpy(&f, &b32, 4);
            return double(f);
        }
        case Type::Float64: {
            double d;
            std::memcpy(&d, &bits, 8);
            return d;
        }
    }
    return 0.0;
}

class Source
{
public:
    Source(const std::string& path, std::ifstream& in, Format f) : path_(path), in_(in), format_(f)
    {
        const auto start = in_.tellg();
        in_.seekg(0, std::ios::end);
        end_ = in_.tellg();
        in_.seekg(start);
        if (format_ != Format::Ascii) {
            // The whole body at once: mapped (its pages all at once, not
            // copied), or else one read instead of millions of small ones
            // into a buffer that is not zeroed first.
            const std::size_t want = end_ > start ? std::size_t(end_ - start) : 0;
            if (!map_body(std::size_t(start), want)) {
                buffer_.reset(new char[want]);
                in_.read(buffer_.get(), std::streamsize(want));
                size_ = std::size_t(in_.gcount());
                body_ = buffer_.get();
            }
            pos_ = 0;
        }
    }
    ~Source()
    {
        if (map_) ::munmap(map_, map_size_);
    }
    Source(const Source&) = delete;
    Source& operator=(const Source&) = delete;

    //! Bytes of the body not read yet.
    std::uint64_t bytes_left()
    {
        if (format_ != Format::Ascii) return size_ - pos_;
        const auto at = in_.tellg();
        return at >= 0 && end_ > at ? std::uint64_t(end_ - at) : 0;
    }

    //! \throw IoError if anything but white space follows the last element.
    void expect_end()
    {
        if (format_ != Format::Ascii) {
            if (pos_ < size_)
                throw IoError(
                    fmt::format("{}: {} bytes after the last element the PLY header declares (a wrong "
                                "count?)",
                                path_, size_ - pos_));
            return;
        }
        std::string tok;
        if (in_ >> tok)
            throw IoError(fmt::format("{}: data after the last element the PLY header declares ({}; a wrong count?)",
                                      path_, quote(tok)));
    }

    double value(Type t)
    {
        if (format_ == Format::Ascii) return ascii_value();
        const std::size_t n = type_size(t);
        if (size_ - pos_ < n) throw IoError(fmt::format("{}: binary PLY ends early (truncated file?)", path_));
        const auto* buf = reinterpret_cast<const unsigned char*>(body_ + pos_);
        pos_ += n;
        return decode(t, buf, format_ == Format::BinaryLE);
    }

    //! Binary bodies: the bytes not read yet (bytes_left() of them), and
    //! skipping \p n of them (at most bytes_left()).
    const unsigned char* here() const { return reinterpret_cast<const unsigned char*>(body_ + pos_); }
    void skip(std::size_t n) { pos_ += n; }

private:
    // Maps the file and points body_ at its bytes [start, start + want) (as
    // many as the file still has); false if it cannot be mapped.
    bool map_body(std::size_t start, std::size_t want)
    {
        if (want == 0) return false;
        const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) return false;
        struct stat st;
        void* m = MAP_FAILED;
        if (::fstat(fd, &st) == 0 && std::size_t(st.st_size) > start) {
            map_size_ = std::size_t(st.st_size);
            m = ::mmap(nullptr, map_size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        }
        ::close(fd);
        if (m == MAP_FAILED) return false;
        map_ = m;
        body_ = static_cast<const char*>(m) + start;
        size_ = std::min(want, map_size_ - start);
        return true;
    }

    double ascii_value()
    {
        std::string tok;
        if (!(in_ >> tok)) throw IoError(fmt::format("{}: ASCII PLY ends early (truncated file?)", path_));
        const char* s = tok.c_str();
        char* end = nullptr;
        const double v = std::strtod(s, &end);
        if (end == s || *end != '\0') throw IoError(fmt::format("{}: {} is not a number", path_, quote(tok)));
        return v;
    }

    const std::string& path_;
    std::ifstream& in_;
    Format format_;
    std::streampos end_ = 0;
    std::unique_ptr<char[]> buffer_;  // the body read, when not mapped
    void* map_ = nullptr;             // the file mapped
    std::size_t map_size_ = 0;
    const char* body_ = nullptr;
    std::size_t size_ = 0;
    std::size_t pos_ = 0;
};

// What the header declares: the body's format and its elements in order.
struct Header
{
    Format format = Format::Ascii;
    std::vector<Element> elements;
};

// The header from the magic line to end_header; leaves `in` at the body.
Header read_header(const std::string& path, std::ifstream& in)
{
    std::string line;
    if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
        throw IoError(fmt::format("{}: not a PLY file (no 'ply' magic line)", path));
    Format format = Format::Ascii;
    bool have_format = false;
    std::vector<Element> elements;
    bool ended = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ss(line);
        std::string word;
        ss >> word;
        if (word.empty() || word == "comment" || word == "obj_info") continue;
        if (word == "format") {
            std::string f;
            ss >> f;
            if (f == "ascii")
                format = Format::Ascii;
            else if (f == "binary_little_endian")
                format = Format::BinaryLE;
            else if (f == "binary_big_endian")
                format = Format::BinaryBE;
            else
                throw IoError(fmt::format("{}: unknown PLY format {}", path, quote(f)));
            have_format = true;
        } else if (word == "element") {
            std::vector<std::string_view> tok;
            split(line, tok);
            std::int64_t count = -1;
            if (tok.size() != 3 || !parse_integer(tok[2], count))
                throw IoError(fmt::format("{}: malformed PLY line {}", path, quote(line)));
            if (count < 0) throw IoError(fmt::format("{}: PLY element {} has a negative count", path, quote(tok[1])));
            Element e;
            e.name = std::string(tok[1]);
            e.count = std::uint64_t(count);
            for (const Element& other : elements)
                if (other.name == e.name)
                    throw IoError(fmt::format("{}: two PLY elements named {}", path, quote(e.name)));
            elements.push_back(e);
        } else if (word == "property") {
            if (elements.empty()) throw IoError(fmt::format("{}: PLY property before any element", path));
            Property p;
            std::string t;
            ss >> t;
            if (t == "list") {
                std::string ct, it;
                ss >> ct >> it >> p.name;
                p.is_list = true;
                if (!parse_type(ct, p.count_type) || !parse_type(it, p.type))
                    throw IoError(fmt::format("{}: malformed PLY line {}", path, quote(line)));
            } else {
                ss >> p.name;
                if (!parse_type(t, p.type)) throw IoError(fmt::format("{}: unknown PLY type in {}", path, quote(line)));
            }
            elements.back().props.push_back(p);
        } else if (word == "end_header") {
            ended = true;
            break;
        } else {
            throw IoError(fmt::format("{}: unexpected PLY header line {}", path, quote(line)));
        }
    }
    if (!ended || !have_format) throw IoError(fmt::format("{}: PLY header without format or end_header", path));
    return {format, std::move(elements)};
}

// Where an element's properties go: the x, y, z and face-index properties
// (-1 if absent) and, per property, its slot in soup.scalar_values (-1 if none).
struct Slots
{
    int ix = -1, iy = -1, iz = -1, iface = -1;
    std::vector<int> scalar_slot;
};

// Finds the slots of element e, adding its extra vertex scalars to the soup.
Slots element_slots(const Element& e, PlySoup& soup)
{
    Slots s;
    for (std::size_t k = 0; k < e.props.size(); ++k) {
        const auto& p = e.props[k];
        if (e.name == "vertex" && !p.is_list) {
            if (p.name == "x") s.ix = int(k);
            if (p.name == "y") s.iy = int(k);
            if (p.name == "z") s.iz = int(k);
        }
        if (e.name == "face" && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) s.iface = int(k);
    }
    s.scalar_slot.assign(e.props.size(), -1);
    if (e.name == "vertex") {
        for (std::size_t k = 0; k < e.props.size(); ++k)
            if (!e.props[k].is_list && int(k) != s.ix && int(k) != s.iy && int(k) != s.iz) {
                s.scalar_slot[k] = int(soup.scalar_names.size());
                soup.scalar_names.push_back(e.props[k].name);
                soup.scalar_values.emplace_back();
            }
    }
    return s;
}

// Reads the e.count rows of element e from the body.
void read_rows(const std::string& path, Source& src, const Element& e, const Slots& s, PlySoup& soup)
{
    double xyz[3] = {0, 0, 0};
    std::vector<int> poly;
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    for (std::uint64_t i = 0; i < e.count; ++i) {
        for (std::size_t k = 0; k < e.props.size(); ++k) {
            const auto& p = e.props[k];
            if (p.is_list) {
                const double cnt = src.value(p.count_type);
                if (!(cnt >= 0 && cnt < 1e6))
                    throw IoError(fmt::format("{}: {} {} has a list of {} entries", path, quote(e.name), i, cnt));
                if (int(k) == s.iface) poly.clear();
                for (std::size_t j = 0; j < std::size_t(cnt); ++j) {
                    const double v = src.value(p.type);
                    if (int(k) == s.iface) {
                        if (!(v >= -2147483648.0 && v <= 2147483647.0))
                            throw IoError(fmt::format("{}: face {} has index {}", path, i, v));
                        poly.push_back(int(v));
                    }
                }
            } else {
                const double v = src.value(p.type);
                if (int(k) == s.ix) xyz[0] = v;
                if (int(k) == s.iy) xyz[1] = v;
                if (int(k) == s.iz) xyz[2] = v;
                if (s.scalar_slot[k] >= 0) soup.scalar_values[std::size_t(s.scalar_slot[k])].push_back(v);
            }
        }
        if (is_vertex) soup.points.emplace_back(xyz[0], xyz[1], xyz[2]);
        if (is_face) soup.polygons.push_back(poly);
    }
}

// Binary rows of fixed size read in parallel, each row from its own offset:
// the same values as read_rows() (decode() as Source::value()), or false
// (nothing read, nothing consumed) where the fast path does not apply or a
// row is not what it assumes, so that read_rows() reads it and reports the
// first problem as before.
//
// A vertex element without list properties: rows of the sum of the
// properties' sizes.
bool read_vertex_rows_parallel(Source& src, Format format, const Element& e, const Slots& s, PlySoup& soup)
{
    if (format == Format::Ascii || e.name != "vertex") return false;
    std::size_t row = 0;
    std::vector<std::size_t> at;
    for (const auto& p : e.props) {
        if (p.is_list) return false;
        at.push_back(row);
        row += type_size(p.type);
    }
    const std::uint64_t n = e.count;
    if (n == 0 || src.bytes_left() / row < n) return false;
    const bool little = format == Format::BinaryLE;
    const unsigned char* body = src.here();
    soup.points.resize(std::size_t(n));  // not zeroed (Eigen): written below
    for (const int slot : s.scalar_slot)
        if (slot >= 0) soup.scalar_values[std::size_t(slot)].resize(std::size_t(n));
    const auto m = std::int64_t(n);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < m; ++i) {
        const unsigned char* r = body + std::size_t(i) * row;
        for (std::size_t k = 0; k < e.props.size(); ++k) {
            const double v = decode(e.props[k].type, r + at[k], little);
            if (int(k) == s.ix) soup.points[std::size_t(i)][0] = v;
            if (int(k) == s.iy) soup.points[std::size_t(i)][1] = v;
            if (int(k) == s.iz) soup.points[std::size_t(i)][2] = v;
            if (s.scalar_slot[k] >= 0) soup.scalar_values[std::size_t(s.scalar_slot[k])][std::size_t(i)] = v;
        }
    }
    src.skip(std::size_t(n) * row);
    return true;
}

// A face element whose one property is its corner list, of an 8-bit count
// and 32-bit indices, every count 3: rows of 13 bytes, triangles.
bool read_triangle_rows_parallel(Source& src, Format format, const Element& e, const Slots& s, PlySoup& soup)
{
    if (format == Format::Ascii || e.name != "face" || e.props.size() != 1 || s.iface != 0) return false;
    const Property& p = e.props[0];
    if (!p.is_list || type_size(p.count_type) != 1 || (p.type != Type::Int32 && p.type != Type::UInt32)) return false;
    constexpr std::size_t row = 13;
    const std::uint64_t n = e.count;
    if (n == 0 || src.bytes_left() / row < n) return false;
    const bool little = format == Format::BinaryLE;
    const unsigned char* body = src.here();
    const auto m = std::int64_t(n);
    CornerArray corners(3 * std::size_t(n));  // not zeroed: every one is written
    // Any row that is not a triangle of indices an int holds: the serial path.
    bool triangles = true;
#pragma omp parallel for schedule(static) reduction(&& : triangles)
    for (std::int64_t i = 0; i < m; ++i) {
        const unsigned char* r = body + std::size_t(i) * row;
        if (decode(p.count_type, r, little) != 3.0) {
            triangles = false;
            continue;
        }
        for (std::size_t j = 0; j < 3; ++j) {
            const double v = decode(p.type, r + 1 + 4 * j, little);
            if (!(v <= 2147483647.0)) triangles = false;  // an unsigned index beyond int
            corners[3 * std::size_t(i) + j] = int(std::min(v, 2147483647.0));
        }
    }
    if (!triangles) return false;
    soup.polygons.assign_uniform(std::move(corners), 3);
    src.skip(std::size_t(n) * row);
    return true;
}

// Checks element e against the header and the bytes left, then reads it.
void read_element(const std::string& path, Source& src, Format format, const Element& e, PlySoup& soup)
{
    const Slots s = element_slots(e, soup);
    if (e.name == "vertex" && (s.ix < 0 || s.iy < 0 || s.iz < 0))
        throw IoError(fmt::format("{}: PLY vertex element lacks x, y or z", path));
    if (e.name == "face" && s.iface < 0) throw IoError(fmt::format("{}: PLY face element lacks vertex_indices", path));
    if (e.props.empty()) return;  // no data, whatever the count
    // Check the count against the bytes left before looping or allocating:
    // an ASCII value takes at least 2 bytes, a binary one its size (a list
    // at least its count).
    std::uint64_t min_bytes = 0;
    for (const auto& p : e.props)
        min_bytes += format == Format::Ascii ? 2 : type_size(p.is_list ? p.count_type : p.type);
    check_count(path, e.count, min_bytes, src.bytes_left(), fmt::format("{} elements", quote(e.name)));
    if (read_vertex_rows_parallel(src, format, e, s, soup) || read_triangle_rows_parallel(src, format, e, s, soup))
        return;
    if (e.name == "vertex") {
        soup.points.reserve(std::size_t(e.count));
        for (const int slot : s.scalar_slot)
            if (slot >= 0) soup.scalar_values[std::size_t(slot)].reserve(std::size_t(e.count));
    }
    if (e.name == "face") soup.polygons.reserve(std::size_t(e.count));
    read_rows(path, src, e, s, soup);
}

}  // namespace

PlySoup read_ply(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(fmt::format("{}: cannot open for reading", path));
    const Header header = read_header(path, in);
    Source src(path, in, header.format);
    PlySoup soup;
    for (const Element& e : header.elements) read_element(path, src, header.format, e, soup);
    src.expect_end();
    return soup;
}

}  // namespace meshdiff::detail
