#include "io/readers/read_util.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <system_error>

namespace meshdiff::detail {

namespace {

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Drops one leading '+' (from_chars takes none); false if what is left is
// empty or starts with another sign.
bool strip_plus(std::string_view& t)
{
    if (!t.empty() && t[0] == '+') {
        t.remove_prefix(1);
        if (!t.empty() && (t[0] == '+' || t[0] == '-')) return false;
    }
    return !t.empty();
}

// For a decimal number from_chars found out of range: true if its magnitude
// is large (overflow), false if small (underflow). The decimal exponent of the
// leading digit decides; out-of-range values are hundreds of decades from 1.
bool magnitude_above_one(std::string_view t)
{
    std::size_t i = 0;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
    long long int_digits = 0;  // digits before the point from the first non-zero one
    long long lead_zeros = 0;  // zeros after the point before the first non-zero digit
    bool point = false, nonzero = false;
    for (; i < t.size() && t[i] != 'e' && t[i] != 'E'; ++i) {
        const char c = t[i];
        if (c == '.') {
            point = true;
        } else if (nonzero || c != '0') {
            nonzero = true;
            if (!point) ++int_digits;
        } else if (point) {
            ++lead_zeros;
        }
    }
    long long e10 = int_digits > 0 ? int_digits - 1 : -lead_zeros - 1;
    if (i < t.size()) {
        ++i;
        bool negative = false;
        if (i < t.size() && (t[i] == '-' || t[i] == '+')) negative = t[i++] == '-';
        long long ex = 0;
        for (; i < t.size() && t[i] >= '0' && t[i] <= '9'; ++i) ex = std::min(ex * 10 + (t[i] - '0'), 1000000000LL);
        e10 += negative ? -ex : ex;
    }
    return e10 > 0;
}

}  // namespace

std::string quote(std::string_view text, std::size_t max_bytes)
{
    std::string out = "'";
    for (const char ch : text.substr(0, max_bytes)) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c < 0x7f && c != '\\')
            out += ch;
        else
            out += fmt::format("\\x{:02x}", c);
    }
    out += '\'';
    if (text.size() > max_bytes) out += "...";
    return out;
}

std::string read_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(fmt::format("{}: cannot open for reading", path));
    std::string text;
    in.seekg(0, std::ios::end);
    const auto end = in.tellg();
    in.seekg(0, std::ios::beg);
    if (end > 0) {
        text.resize(std::size_t(end));
        in.read(text.data(), std::streamsize(text.size()));
        text.resize(std::size_t(in.gcount()));
    }
    if (in.bad()) throw IoError(fmt::format("{}: read error", path));
    return text;
}

void split(std::string_view line, std::vector<std::string_view>& tokens)
{
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        const std::size_t b = i;
        while (i < line.size() && !is_space(line[i])) ++i;
        if (i > b) tokens.push_back(line.substr(b, i - b));
    }
}

bool TextLines::next_tokens(std::vector<std::string_view>& tokens)
{
    while (pos_ < text_.size()) {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        std::string_view line = text_.substr(pos_, end - pos_);
        pos_ = end < text_.size() ? end + 1 : end;
        ++line_;
        if (comment_ != '\0') line = line.substr(0, line.find(comment_));
        split(line, tokens);
        if (!tokens.empty()) return true;
    }
    tokens.clear();
    return false;
}

Number parse_double(std::string_view token, double& value)
{
    if (!strip_plus(token)) return Number::Invalid;
    const char* end = token.data() + token.size();
    const auto r = std::from_chars(token.data(), end, value);
    if (r.ptr != end) return Number::Invalid;
    if (r.ec == std::errc::result_out_of_range) {
        const double sign = token[0] == '-' ? -1.0 : 1.0;
        if (magnitude_above_one(token)) {
            value = sign * std::numeric_limits<double>::infinity();
            return Number::Overflow;
        }
        value = sign * 0.0;
        return Number::Ok;
    }
    if (r.ec != std::errc()) return Number::Invalid;
    return std::isfinite(value) ? Number::Ok : Number::NotFinite;
}

Number parse_float_coordinate(std::string_view token, double& value)
{
    const Number n = parse_double(token, value);
    if (n != Number::Ok) return n;
    strip_plus(token);
    float f = 0.0f;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), f);
    if (r.ec == std::errc())
        value = double(f);
    else if (std::fabs(value) < 1.0)
        value = double(float(value));  // below float's range: 0 or subnormal
    // else beyond float's range: keep the double, which the limit refuses
    return Number::Ok;
}

bool parse_integer(std::string_view token, std::int64_t& value)
{
    if (!strip_plus(token)) return false;
    const char* end = token.data() + token.size();
    const auto r = std::from_chars(token.data(), end, value);
    if (r.ptr != end) return false;
    if (r.ec == std::errc::result_out_of_range) {
        value = token[0] == '-' ? std::numeric_limits<std::int64_t>::min() : std::numeric_limits<std::int64_t>::max();
        return true;
    }
    return r.ec == std::errc();
}

void check_count(const std::string& path, std::uint64_t count, std::uint64_t min_bytes, std::uint64_t bytes_left,
                 std::string_view what)
{
    if (min_bytes == 0 || count <= (bytes_left + 1) / min_bytes) return;
    throw IoError(
        fmt::format("{}: the header declares {} {}, more than the {} bytes after it can hold (a corrupt "
                    "count or a truncated file)",
                    path, count, what, bytes_left));
}

}  // namespace meshdiff::detail
