#include "meshdiff/distance/sample_cloud.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/point_triangle.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

struct Record
{
    Vec3 point;
    double distance;
    double signed_distance;
    std::uint8_t kind, direction;
    std::int32_t face;
};

// Reads the file back: the header lines and the records.
std::vector<Record> read_back(const std::filesystem::path& path, std::vector<std::string>& header)
{
    std::ifstream in(path, std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t end = all.find("end_header\n") + std::string("end_header\n").size();
    std::size_t at = 0;
    while (at < end) {
        const std::size_t nl = all.find('\n', at);
        header.push_back(all.substr(at, nl - at));
        at = nl + 1;
    }
    std::vector<Record> r((all.size() - end) / kSampleCloudStride);
    EXPECT_EQ((all.size() - end) % kSampleCloudStride, 0u);
    const char* p = all.data() + end;
    for (Record& x : r) {
        std::memcpy(x.point.data(), p, 24);
        std::memcpy(&x.distance, p + 24, 8);
        std::memcpy(&x.signed_distance, p + 32, 8);
        std::memcpy(&x.kind, p + 40, 1);
        std::memcpy(&x.direction, p + 41, 1);
        std::memcpy(&x.face, p + 42, 4);
        p += kSampleCloudStride;
    }
    return r;
}

}  // namespace

TEST(SampleCloud, BothDirectionsReadBackWithExactDistances)
{
    const Mesh a = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const Mesh b = read_mesh(kData + "/hemisphere.ply").mesh;
    SamplingOptions o;
    o.samples = 2000;
    const SampledSurfaceDistance r = surface_distance_samples(a, b, o);
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "meshdiff_sample_cloud_test.ply";
    write_sample_cloud(path, a, r.forward, b, r.backward, {"original a.ply"});
    std::vector<std::string> header;
    const std::vector<Record> rec = read_back(path, header);
    std::filesystem::remove(path);
    EXPECT_EQ(header[1], "format binary_little_endian 1.0");
    EXPECT_NE(std::find(header.begin(), header.end(), "comment original a.ply"), header.end());
    EXPECT_NE(std::find(header.begin(), header.end(),
                        "element vertex " + std::to_string(r.forward.samples.size() + r.backward.samples.size())),
              header.end());
    ASSERT_EQ(rec.size(), r.forward.samples.size() + r.backward.samples.size());
    std::size_t n_forward = 0, by_kind[2][3] = {};
    for (std::size_t i = 0; i < rec.size(); ++i) {
        const Record& x = rec[i];
        ASSERT_LE(x.direction, 1);
        ASSERT_LE(x.kind, 2);
        ++by_kind[x.direction][x.kind];
        n_forward += x.direction == 0;
        // The distance is the exact distance to the other surface (brute force);
        // the face of the sampled mesh holds the sample.
        const Mesh& from = x.direction == 0 ? a : b;
        const Mesh& to = x.direction == 0 ? b : a;
        if (i % 13 == 0) {
            EXPECT_NEAR(x.distance, closest_point_brute_force(to, x.point).distance, 1e-12 * x.distance + 1e-300);
            ASSERT_GE(x.face, 0);
            ASSERT_LT(std::size_t(x.face), from.n_faces());
            const Face& t = from.faces[std::size_t(x.face)];
            EXPECT_LT(closest_point_on_triangle(x.point, from.points[std::size_t(t[0])], from.points[std::size_t(t[1])],
                                                from.points[std::size_t(t[2])])
                          .distance,
                      1e-12);
        }
    }
    EXPECT_EQ(n_forward, r.forward.samples.size());
    EXPECT_EQ(by_kind[0][0], r.forward.samples.n_vertex);
    EXPECT_EQ(by_kind[0][1], r.forward.samples.n_edge);
    EXPECT_EQ(by_kind[0][2], r.forward.samples.n_face);
    EXPECT_EQ(by_kind[1][2], r.backward.samples.n_face);
    // Forward records first, in sample order.
    EXPECT_EQ(rec[0].point, r.forward.samples.points[0]);
    EXPECT_EQ(rec[n_forward].point, r.backward.samples.points[0]);
    // The hemisphere (the target of the forward direction) is open: no sign there, NaN, and a comment says so.
    ASSERT_TRUE(r.forward.signed_distances.empty());
    for (std::size_t i = 0; i < n_forward; ++i) EXPECT_TRUE(std::isnan(rec[i].signed_distance));
    EXPECT_NE(std::find(header.begin(), header.end(),
                        "comment signed_distance is NaN in the forward direction: its other surface cannot be "
                        "signed against"),
              header.end());
    EXPECT_NE(std::find(header.begin(), header.end(), "property double signed_distance"), header.end());
}

TEST(SampleCloud, SignedDistanceColumn)
{
    // Two spheres, the processed one inside: forward samples outside the
    // processed surface (+), backward ones inside the original (-).
    const Mesh a = icosphere(2, 1.0).mesh;
    const Mesh b = icosphere(2, 0.8).mesh;
    SamplingOptions o;
    o.samples = 3000;
    const SampledSurfaceDistance r = surface_distance_samples(a, b, o);
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "meshdiff_sample_cloud_signed.ply";
    write_sample_cloud(path, a, r.forward, b, r.backward);
    std::vector<std::string> header;
    const std::vector<Record> rec = read_back(path, header);
    std::filesystem::remove(path);
    ASSERT_EQ(rec.size(), r.forward.samples.size() + r.backward.samples.size());
    for (const Record& x : rec) {
        ASSERT_GT(x.distance, 0.1);
        EXPECT_EQ(x.signed_distance, x.direction == 0 ? x.distance : -x.distance);
    }
    for (const std::string& h : header) EXPECT_EQ(h.find("is NaN"), std::string::npos) << h;
}

TEST(SampleCloud, MismatchedSamplesThrow)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    SampledSurfaceDistance r = surface_distance_samples(a, a);
    r.forward.distances.pop_back();
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "meshdiff_sample_cloud_bad.ply";
    EXPECT_THROW(write_sample_cloud(path, a, r.forward, a, r.backward), InvalidArgumentError);
    EXPECT_FALSE(std::filesystem::exists(path));
}
