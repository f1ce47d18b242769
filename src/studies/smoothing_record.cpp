#include "meshdiff/studies/smoothing_record.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace meshdiff {

ProfileOptions record_profile_defaults()
{
    ProfileOptions p;
    p.levels = {1, 5, 10, 20};
    return p;
}

void check_recording(int every, bool has_output)
{
    if (every < 0 || every > kMaxRecordEvery)
        throw OptionError("record.every",
                          fmt::format("{} is outside 1..{} (0: first and last only)", every, kMaxRecordEvery));
    if (every > 0 && !has_output) throw OptionError("record.every", "needs {record.output}: where to write the record");
}

SmoothingRecord smooth_and_record(Mesh& mesh, const SmoothingOptions& options, const RecordOptions& record)
{
    check_recording(record.every, true);
    const int every = record.every > 0 ? record.every : std::max(1, options.iterations);
    const int last = options.iterations;
    SmoothingRecord r;
    const Mesh input = record.distance ? mesh : Mesh();
    SmoothingOptions o = options;
    o.callback = [&](int k, const Mesh& state) {
        if (options.callback) options.callback(k, state);
        if (k % every != 0 && k != last) return;
        const RoughnessProfile p = roughness_profile(state, record.profile);
        r.iterations.push_back(k);
        std::vector<double> sigma;
        for (const auto& l : p.levels) sigma.push_back(l.sigma);
        r.sigma.push_back(std::move(sigma));
        if (p.has_global) r.sigma_global.push_back(p.global.sigma);
        r.undefined.push_back(p.curvature_undefined);
        if (record.distance) r.distance.push_back(surface_distance(input, state, record.sampling));
    };
    r.report = smooth(mesh, o);
    if (!r.report.steps.empty()) {
        for (int k : r.iterations) {
            double t = 0;
            for (std::size_t i = 0; i < std::size_t(k) && i < r.report.steps.size(); ++i) t += r.report.steps[i];
            r.flow_time.push_back(t);
        }
    }
    return r;
}

}  // namespace meshdiff
