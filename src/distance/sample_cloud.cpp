#include "meshdiff/distance/sample_cloud.h"

#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

namespace meshdiff {

namespace {

// Per vertex, the lowest-index face using it (-1 for an unreferenced vertex).
std::vector<std::int32_t> first_face_of_vertex(const Mesh& m)
{
    std::vector<std::int32_t> first(m.n_vertices(), -1);
    for (std::size_t f = m.n_faces(); f-- > 0;)
        for (auto v : m.faces[f]) first[std::size_t(v)] = std::int32_t(f);
    return first;
}

void check(const char* name, const Mesh& m, const SampledDirection& d)
{
    const SurfaceSamples& s = d.samples;
    if (d.distances.size() != s.size() || s.kind.size() != s.size() || s.element.size() != s.size() ||
        (!d.signed_distances.empty() && d.signed_distances.size() != s.size()))
        throw InvalidArgumentError(
            fmt::format("write_sample_cloud: {} direction has {} samples, {} distances, {} "
                        "kinds and {} elements",
                        name, s.size(), d.distances.size(), s.kind.size(), s.element.size()));
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool per_vertex = s.kind[i] == SampleKind::OnVertex || s.kind[i] == SampleKind::OnPoint;
        const std::size_t n = per_vertex ? m.n_vertices() : m.n_faces();
        if (s.element[i] >= n)
            throw InvalidArgumentError(
                fmt::format("write_sample_cloud: {} sample {} names element {} of {}", name, i, s.element[i], n));
    }
}

}  // namespace

void write_sample_cloud(const std::filesystem::path& path, const Mesh& a, const SampledDirection& forward,
                        const Mesh& b, const SampledDirection& backward, const std::vector<std::string>& comments)
{
    check("forward", a, forward);
    check("backward", b, backward);
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw IoError(fmt::format("{}: cannot open for writing", path.string()));
        out << "ply\nformat binary_little_endian 1.0\ncomment written by meshdiff: surface distance samples\n";
        out << "comment direction 0 = forward (a sample of the original, distance to the processed surface), "
               "1 = backward (a sample of the processed mesh, distance to the original surface)\n";
        out << "comment kind 0 = vertex, 1 = edge, 2 = face; face = the face sampled (edge: the lowest-index face "
               "having the edge; vertex: the lowest-index face using the vertex) of the sampled mesh\n";
        const auto has_points = [](const SampledDirection& d) {
            return std::find(d.samples.kind.begin(), d.samples.kind.end(), SampleKind::OnPoint) != d.samples.kind.end();
        };
        if (has_points(forward) || has_points(backward))
            out << "comment kind 3 = point of a point cloud (face -1; the points of a cloud are its samples)\n";
        out << "comment signed_distance: positive outside the other surface, negative inside, 0 on it "
               "(angle-weighted pseudo-normals)\n";
        for (const auto& [name, d] : {std::pair{"forward", &forward}, {"backward", &backward}})
            if (d->signed_distances.empty())
                out << "comment signed_distance is NaN in the " << name
                    << " direction: its other surface cannot be signed against\n";
        for (std::string c : comments) {
            std::replace_if(
                c.begin(), c.end(), [](char ch) { return ch == '\n' || ch == '\r'; }, ' ');
            out << "comment " << c << "\n";
        }
        out << "element vertex " << forward.samples.size() + backward.samples.size() << "\n";
        out << "property double x\nproperty double y\nproperty double z\nproperty double distance\n"
               "property double signed_distance\n";
        out << "property uchar kind\nproperty uchar direction\nproperty int face\nend_header\n";
        static_assert(sizeof(double) == 8 && sizeof(std::int32_t) == 4, "PLY types");
        std::uint8_t direction = 0;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (const auto& [mesh, d] : {std::pair{&a, &forward}, {&b, &backward}}) {
            const std::vector<std::int32_t> first = first_face_of_vertex(*mesh);
            const SurfaceSamples& s = d->samples;
            std::vector<char> buf(kSampleCloudStride * s.size());
            char* p = buf.data();
            for (std::size_t i = 0; i < s.size(); ++i) {
                std::memcpy(p, s.points[i].data(), 24);
                std::memcpy(p + 24, &d->distances[i], 8);
                const double sd = d->signed_distances.empty() ? nan : d->signed_distances[i];
                std::memcpy(p + 32, &sd, 8);
                const auto kind = std::uint8_t(s.kind[i]);
                const std::int32_t face = s.kind[i] == SampleKind::OnVertex  ? first[s.element[i]]
                                          : s.kind[i] == SampleKind::OnPoint ? -1
                                                                             : std::int32_t(s.element[i]);
                std::memcpy(p + 40, &kind, 1);
                std::memcpy(p + 41, &direction, 1);
                std::memcpy(p + 42, &face, 4);
                p += kSampleCloudStride;
            }
            out.write(buf.data(), std::streamsize(buf.size()));
            ++direction;
        }
        out.close();
        if (!out) throw IoError(fmt::format("{}: write failed", path.string()));
    });
}

}  // namespace meshdiff
