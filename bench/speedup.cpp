// The speed-up from 1 to 2 threads (or any list) of each stage of a compare,
// timed through the library's Progress interface (meshdiff/core/progress.h): a
// stage runs from its Progress::stage() call to the next one, so the serial
// steps between stages count in the stage before them ("setup" is the time
// from the call to the first stage: normalisation, adjacency, normals).
// Wall and CPU time (all threads of the process) per stage, summed over both
// meshes and both directions; the median of --repeat runs per thread count,
// the runs of the thread counts interleaved so that a noisy machine hurts
// them alike.
// Usage: meshdiff_bench_speedup A.ply B.ply [--repeat 3] [--threads 1,2] [--radii 0.05 | none]
#include "bench_common.h"

#include "meshdiff/compare.h"
#include "meshdiff/core/progress.h"
#include "meshdiff/io/io.h"

#include <fmt/format.h>
#include <omp.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace meshdiff;
using Clock = std::chrono::steady_clock;

using namespace meshdiff::timing;

namespace {

struct Time
{
    double wall = 0.0, cpu = 0.0;
};

// Wall and CPU time per stage name, in the order first seen.
class StageClock : public Progress
{
public:
    void stage(std::string_view name, std::size_t) override { start(std::string(name)); }
    void start(const std::string& name)
    {
        stop();
        current_ = name;
        if (!times.count(name)) order.push_back(name);
        wall0_ = Clock::now();
        cpu0_ = cpu_seconds();
    }
    void stop()
    {
        if (current_.empty()) return;
        Time& t = times[current_];
        t.wall += std::chrono::duration<double>(Clock::now() - wall0_).count();
        t.cpu += cpu_seconds() - cpu0_;
        current_.clear();
    }
    std::map<std::string, Time> times;
    std::vector<std::string> order;

private:
    std::string current_;
    Clock::time_point wall0_;
    double cpu0_ = 0.0;
};

std::vector<double> numbers(const std::string& text)
{
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
    return v;
}

}  // namespace

int main(int argc, char** argv)
{
    int repeat = 3;
    std::vector<int> threads{1, 2};
    std::vector<double> radii{0.05};
    const std::vector<int> levels = default_levels();  // 1..20, as the CLI
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--repeat" && i + 1 < argc) {
            repeat = std::max(1, std::stoi(argv[++i]));
        } else if (a == "--threads" && i + 1 < argc) {
            threads.clear();
            for (double t : numbers(argv[++i])) threads.push_back(int(t));
        } else if (a == "--radii" && i + 1 < argc) {
            const std::string v = argv[++i];
            radii = v == "none" ? std::vector<double>{} : numbers(v);
        } else {
            paths.push_back(a);
        }
    }
    if (paths.size() != 2) {
        fmt::print(stderr, "usage: meshdiff_bench_speedup A.ply B.ply [--repeat N] [--threads 1,2] [--radii R,...]\n");
        return 2;
    }
    // Per thread count, per stage: the runs' times.
    std::map<int, std::map<std::string, std::vector<Time>>> runs;
    std::vector<std::string> order;
    for (int r = 0; r < repeat; ++r)
        for (const int t : threads) {
            omp_set_num_threads(t);
            StageClock clock;
            const auto t0 = Clock::now();
            const double c0 = cpu_seconds();
            clock.start("reading");
            const LoadedMesh a = read_mesh(paths[0]);
            const LoadedMesh b = read_mesh(paths[1]);
            clock.start("setup");
            CompareOptions o;
            o.profile.levels = levels;  // and the global level
            o.profile.radii = radii;
            o.progress = &clock;
            const Comparison c = compare_meshes(a, b, o);
            clock.stop();
            clock.times["total"] = {std::chrono::duration<double>(Clock::now() - t0).count(), cpu_seconds() - c0};
            clock.order.push_back("total");
            if (order.empty()) order = clock.order;
            std::string line = fmt::format("run {} threads {}:", r + 1, t);
            for (const auto& name : clock.order) {
                runs[t][name].push_back(clock.times[name]);
                line += fmt::format("  {} {:.2f} ({:.2f} cpu)", name, clock.times[name].wall, clock.times[name].cpu);
            }
            fmt::print("{}\n", line);
            if (!c.distance) return 1;
        }
    fmt::print("\n{} vs {}: {} vertices / {} faces, median of {} runs; wall and CPU seconds\n\n", paths[0], paths[1],
               read_mesh(paths[0]).mesh.n_vertices(), read_mesh(paths[0]).mesh.n_faces(), repeat);
    std::string head = "| stage |", rule = "|---|";
    for (const int t : threads) {
        head += fmt::format(" wall, {} thread{} | CPU, {} thread{} |", t, t == 1 ? "" : "s", t, t == 1 ? "" : "s");
        rule += "---:|---:|";
    }
    if (threads.size() == 2) {
        head += fmt::format(" speed-up {} -> {} |", threads[0], threads[1]);
        rule += "---:|";
    }
    fmt::print("{}\n{}\n", head, rule);
    for (const auto& name : order) {
        std::string row = fmt::format("| {} |", name);
        std::vector<double> wall;
        for (const int t : threads) {
            std::vector<double> w, c;
            for (const Time& x : runs[t][name]) {
                w.push_back(x.wall);
                c.push_back(x.cpu);
            }
            wall.push_back(median(w));
            row += fmt::format(" {:.2f} | {:.2f} |", median(w), median(c));
        }
        if (threads.size() == 2) row += fmt::format(" {:.2f} |", wall[1] > 0 ? wall[0] / wall[1] : 0.0);
        fmt::print("{}\n", row);
    }
    return 0;
}
