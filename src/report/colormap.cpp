#include "meshdiff/report/colormap.h"

#include <algorithm>
#include <cmath>

namespace meshdiff {

namespace {
std::uint8_t to_byte(double x)
{
    return std::uint8_t(std::lround(std::clamp(x, 0.0, 1.0) * 255.0));
}
const Rgb kGrey = {128, 128, 128};
}  // namespace

std::vector<Rgb> diverging_colors(const std::vector<double>& values, double range)
{
    std::vector<Rgb> out(values.size(), kGrey);
    if (!(range > 0.0)) range = 1.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::isnan(values[i])) continue;
        const double t = std::clamp(values[i] / range, -1.0, 1.0);
        // t = -1 blue (0.23, 0.30, 0.75), 0 white, +1 red (0.71, 0.02, 0.15).
        const double r = t < 0 ? 1.0 + t * (1.0 - 0.23) : 1.0 - t * (1.0 - 0.71);
        const double g = t < 0 ? 1.0 + t * (1.0 - 0.30) : 1.0 - t * (1.0 - 0.02);
        const double b = t < 0 ? 1.0 + t * (1.0 - 0.75) : 1.0 - t * (1.0 - 0.15);
        out[i] = {to_byte(r), to_byte(g), to_byte(b)};
    }
    return out;
}

std::vector<Rgb> sequential_colors(const std::vector<double>& values, double lo, double hi)
{
    std::vector<Rgb> out(values.size(), kGrey);
    const double span = hi > lo ? hi - lo : 1.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::isnan(values[i])) continue;
        const double t = std::clamp((values[i] - lo) / span, 0.0, 1.0) * 4.0;
        double r, g, b;
        if (t < 1) {
            r = 0, g = t, b = 1;
        } else if (t < 2) {
            r = 0, g = 1, b = 2 - t;
        } else if (t < 3) {
            r = t - 2, g = 1, b = 0;
        } else {
            r = 1, g = 4 - t, b = 0;
        }
        out[i] = {to_byte(r), to_byte(g), to_byte(b)};
    }
    return out;
}

double robust_symmetric_range(const std::vector<double>& values)
{
    std::vector<double> a;
    a.reserve(values.size());
    for (double v : values)
        if (!std::isnan(v)) a.push_back(std::abs(v));
    if (a.empty()) return 1.0;
    const auto k = std::size_t(0.95 * double(a.size() - 1));
    std::nth_element(a.begin(), a.begin() + std::ptrdiff_t(k), a.end());
    return a[k] > 0.0 ? a[k] : 1.0;
}

}  // namespace meshdiff
