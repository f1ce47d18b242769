// The meshes as the HTML report draws them: reduced by vertex clustering
// above a face budget (html.h: reduce_for_display()).
#include "meshdiff/report/html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace meshdiff {

namespace {

// One clustering of \p mesh on a grid of \p cells cells along its longest side.
struct Clustering
{
    std::vector<std::uint32_t> cluster;  // per vertex
    std::size_t clusters = 0;
    std::vector<std::uint32_t> indices;  // the faces that keep three clusters
};

Clustering cluster(const Mesh& mesh, double cells)
{
    const BoundingBox box = bounding_box(mesh);
    const Vec3 size = box.max - box.min;
    const double side = std::max({size.x(), size.y(), size.z(), 1e-300});
    const double h = side / cells;
    Clustering c;
    c.cluster.resize(mesh.n_vertices());
    std::unordered_map<std::uint64_t, std::uint32_t> ids;
    ids.reserve(mesh.n_vertices() / 2 + 1);
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
        const Vec3 q = (mesh.points[v] - box.min) / h;
        auto cell = [](double x) { return std::uint64_t(std::clamp(x, 0.0, 2097151.0)); };
        const std::uint64_t key = cell(q.x()) | cell(q.y()) << 21 | cell(q.z()) << 42;
        const auto [it, added] = ids.emplace(key, std::uint32_t(c.clusters));
        if (added) ++c.clusters;
        c.cluster[v] = it->second;
    }
    for (const Face& f : mesh.faces) {
        const std::uint32_t a = c.cluster[std::size_t(f[0])], b = c.cluster[std::size_t(f[1])],
                            d = c.cluster[std::size_t(f[2])];
        if (a == b || b == d || a == d) continue;
        c.indices.insert(c.indices.end(), {a, b, d});
    }
    return c;
}

}  // namespace

DisplayMesh reduce_for_display(const Mesh& mesh, const std::vector<const std::vector<double>*>& values,
                               std::size_t face_budget)
{
    DisplayMesh d;
    d.full_vertices = mesh.n_vertices();
    d.full_faces = mesh.n_faces();
    d.values.resize(values.size());
    if (mesh.n_faces() <= face_budget) {
        d.positions.reserve(3 * mesh.n_vertices());
        for (const Vec3& p : mesh.points)
            for (int k = 0; k < 3; ++k) d.positions.push_back(float(p[k]));
        d.indices.reserve(3 * mesh.n_faces());
        for (const Face& f : mesh.faces)
            for (int k = 0; k < 3; ++k) d.indices.push_back(std::uint32_t(f[std::size_t(k)]));
        for (std::size_t i = 0; i < values.size(); ++i) d.values[i].assign(values[i]->begin(), values[i]->end());
        return d;
    }
    // A closed surface on an N^3 grid keeps about 12 N^2 faces: start there, coarsen by 15% until within budget.
    double cells = std::sqrt(double(face_budget) / 4.0);
    Clustering c = cluster(mesh, cells);
    while (c.indices.size() / 3 > face_budget && cells > 2.0) {
        cells *= 0.85;
        c = cluster(mesh, cells);
    }
    d.reduced = true;
    d.indices = std::move(c.indices);
    std::vector<double> sum(3 * c.clusters, 0.0);
    std::vector<std::uint32_t> count(c.clusters, 0);
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
        const std::size_t k = c.cluster[v];
        for (int a = 0; a < 3; ++a) sum[3 * k + std::size_t(a)] += mesh.points[v][a];
        ++count[k];
    }
    d.positions.resize(3 * c.clusters);
    for (std::size_t i = 0; i < sum.size(); ++i) d.positions[i] = float(sum[i] / count[i / 3]);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::vector<double>& out = d.values[i];
        out.assign(c.clusters, nan);
        for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
            const double x = (*values[i])[v];
            double& o = out[c.cluster[v]];
            if (!std::isnan(x) && (std::isnan(o) || std::abs(x) > std::abs(o))) o = x;
        }
    }
    return d;
}

}  // namespace meshdiff
