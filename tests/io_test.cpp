#include "meshdiff/io/io.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/error.h"
#include "meshdiff/studies/shapes.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir()
{
    const fs::path d = fs::temp_directory_path() / ("meshdiff_io_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

fs::path write_text(const std::string& name, const std::string& text)
{
    const fs::path p = temp_dir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

template <class E>
std::string error_of(const fs::path& p)
{
    try {
        read_mesh(p);
    } catch (const E& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(ReadMesh, AsciiPlyWithExtraVertexProperties)
{
    const LoadedMesh m = read_mesh(data("bunny_res4_ascii.ply"));
    EXPECT_EQ(m.input.file_vertices, 453u);
    EXPECT_EQ(m.input.file_faces, 948u);
    EXPECT_EQ(m.mesh.n_vertices(), 453u);
    EXPECT_EQ(m.mesh.n_faces(), 948u);
    // First vertex of the file: -0.0312216 0.126304 (declared float).
    EXPECT_EQ(m.mesh.points[0].x(), -0.0312216);  // ASCII is parsed in double
    EXPECT_EQ(m.mesh.points[0].y(), 0.126304);
}

TEST(ReadMesh, BinaryPlyObjAndDroppedUnreferencedVertices)
{
    const LoadedMesh sphere = read_mesh(data("sphere_ico_2562.ply"));
    EXPECT_EQ(sphere.mesh.n_vertices(), 2562u);
    EXPECT_EQ(sphere.mesh.n_faces(), 5120u);
    for (const auto& p : sphere.mesh.points) EXPECT_NEAR(p.norm(), 1.0, 1e-6);
    const LoadedMesh teapot = read_mesh(data("teapot.obj"));
    EXPECT_EQ(teapot.mesh.n_vertices(), 3644u);
    EXPECT_EQ(teapot.mesh.n_faces(), 6320u);
    const LoadedMesh bunny = read_mesh(data("bunny_res3.ply"));
    EXPECT_EQ(bunny.input.file_vertices, 1889u);
    EXPECT_EQ(bunny.input.unreferenced_vertices, 2u);
    EXPECT_EQ(bunny.mesh.n_vertices(), 1887u);
}

TEST(ReadMesh, BinaryPlyScalarsFollowTheVerticesKeptWithAndWithoutUnreferencedOnes)
{
    // Every vertex used: the file's numbering and values as they are (the
    // body mapped, nothing copied); vertex 0 unused: it and its value dropped,
    // the rest renumbered.
    const Shape s = icosphere(1);
    const fs::path all = temp_dir() / "all_used.ply";
    write_ply(all, s.mesh, {{"H", s.exact_H}});
    const LoadedMesh a = read_mesh(all);
    EXPECT_EQ(a.input.unreferenced_vertices, 0u);
    EXPECT_TRUE(a.mesh.points == s.mesh.points);
    EXPECT_EQ(a.mesh.faces, s.mesh.faces);
    EXPECT_EQ(vertex_scalar(a, "H").values, s.exact_H);

    Mesh m = s.mesh;
    m.points.insert(m.points.begin(), Vec3(9, 9, 9));
    for (Face& f : m.faces)
        for (int& v : f) ++v;
    std::vector<double> h = s.exact_H;
    h.insert(h.begin(), 42.0);
    const fs::path one = temp_dir() / "one_unused.ply";
    write_ply(one, m, {{"H", h}});
    const LoadedMesh b = read_mesh(one);
    EXPECT_EQ(b.input.unreferenced_vertices, 1u);
    EXPECT_TRUE(b.mesh.points == s.mesh.points);
    EXPECT_EQ(b.mesh.faces, s.mesh.faces);
    EXPECT_EQ(vertex_scalar(b, "H").values, s.exact_H);
}

TEST(ReadMesh, OffWithPolygonsAndStlRoundTrip)
{
    const auto off = write_text("quad.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n9 9 9\n4 0 1 2 3\n3 0 2 1\n");
    const LoadedMesh m = read_mesh(off);
    EXPECT_EQ(m.input.polygons_triangulated, 1u);
    EXPECT_EQ(m.mesh.n_faces(), 3u);
    EXPECT_EQ(m.input.unreferenced_vertices, 1u);
    const Shape s = icosphere(2);
    const fs::path stl = temp_dir() / "ico.stl";
    write_mesh(stl, s.mesh);
    const LoadedMesh back = read_mesh(stl);
    EXPECT_EQ(back.mesh.n_faces(), s.mesh.n_faces());
    EXPECT_EQ(back.mesh.n_vertices(), s.mesh.n_vertices());  // the STL reader welds corners
}

TEST(WritePly, RoundTripKeepsDoublePrecisionAndProperties)
{
    Shape s = icosphere(2);
    s.mesh.points[0] += Vec3(1e-13, 0, 0);
    const fs::path p = temp_dir() / "ico.ply";
    write_ply(p, s.mesh, {{"H", s.exact_H}}, std::vector<std::array<std::uint8_t, 3>>(s.mesh.n_vertices(), {1, 2, 3}));
    const LoadedMesh back = read_mesh(p);
    ASSERT_EQ(back.mesh.n_vertices(), s.mesh.n_vertices());
    EXPECT_EQ(back.mesh.points[0], s.mesh.points[0]);
    EXPECT_EQ(back.mesh.faces, s.mesh.faces);
    EXPECT_THROW(write_ply(p, s.mesh, {{"H", {1.0}}}), InvalidArgumentError);
}

TEST(ReadMesh, BadInputsGiveOneClearErrorNamingTheFile)
{
    EXPECT_NE(error_of<IoError>("/nonexistent/x.ply").find("/nonexistent/x.ply: no such file"), std::string::npos);
    const auto empty = write_text("empty.ply", "");
    EXPECT_NE(error_of<IoError>(empty).find("empty.ply: file is empty"), std::string::npos);
    const auto unknown = write_text("mesh.xyz", "1 2 3\n");
    EXPECT_NE(error_of<IoError>(unknown).find("unknown mesh format"), std::string::npos);
    EXPECT_NE(error_of<IoError>(temp_dir()).find("directory"), std::string::npos);

    // A binary PLY cut in the middle of its face list.
    std::ifstream in(data("sphere_ico_2562.ply"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto truncated = write_text("truncated.ply", bytes.substr(0, bytes.size() * 2 / 3));
    const std::string msg = error_of<IoError>(truncated);
    EXPECT_NE(msg.find("truncated.ply"), std::string::npos) << msg;

    for (const char* name : {"nan.off", "nan.obj", "nan.ply"}) {
        const std::string text = std::string(name) == "nan.off" ? "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"
                                 : std::string(name) == "nan.obj"
                                     ? "v 0 0 0\nv 0 nan 0\nv 0 1 0\nf 1 2 3\n"
                                     : "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty "
                                       "float y\nproperty float z\nelement face 1\nproperty list uchar int "
                                       "vertex_indices\nend_header\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n";
        const auto p = write_text(name, text);
        const std::string nan_msg = error_of<InvalidMeshError>(p);
        EXPECT_NE(nan_msg.find("non-finite"), std::string::npos) << nan_msg;
        EXPECT_NE(nan_msg.find(name), std::string::npos) << nan_msg;
    }
    const auto noface = write_text("noface.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    EXPECT_NE(error_of<InvalidMeshError>(noface).find("no faces"), std::string::npos);
    const auto badindex = write_text("badindex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    const std::string bi = error_of<InvalidMeshError>(badindex);
    EXPECT_NE(bi.find("badindex.off"), std::string::npos) << bi;
    const auto garbage = write_text("garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_header\nfoo\n");
    const std::string g = error_of<Error>(garbage);
    EXPECT_NE(g.find("garbage.ply"), std::string::npos) << g;
}

TEST(ReadMesh, RepeatedCornersAreDroppedAndCounted)
{
    const auto p = write_text("rep.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 1 2\n3 1 3 2\n");
    const LoadedMesh m = read_mesh(p);
    EXPECT_EQ(m.input.repeated_index_faces, 1u);
    EXPECT_EQ(m.mesh.n_faces(), 2u);
}

namespace {

// A PLY of n vertices (float x y z, uchar q, short s) and the given polygons
// (list uchar `index_type`), as ASCII (row by row, the reference), binary
// little- or big-endian (whose triangle-only files are read in parallel).
std::string ply_bytes(const std::string& format, const std::vector<std::array<float, 3>>& xyz,
                      const std::vector<std::vector<std::int64_t>>& polygons, const std::string& index_type)
{
    std::string out = "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(xyz.size()) +
                      "\nproperty float x\nproperty uchar q\nproperty float y\nproperty float z\nproperty short s\n"
                      "element face " +
                      std::to_string(polygons.size()) + "\nproperty list uchar " + index_type +
                      " vertex_indices\nend_header\n";
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    auto put = [&](const void* v, std::size_t n) {
        const auto* b = static_cast<const char*>(v);
        for (std::size_t i = 0; i < n; ++i) out += b[big ? n - 1 - i : i];
    };
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        const auto q = std::uint8_t(i % 251);
        const auto s = std::int16_t(int(i % 60000) - 30000);
        if (ascii) {
            out += fmt::format("{:.17g} {} {:.17g} {:.17g} {}\n", double(xyz[i][0]), q, double(xyz[i][1]),
                               double(xyz[i][2]), s);
            continue;
        }
        put(&xyz[i][0], 4);
        put(&q, 1);
        put(&xyz[i][1], 4);
        put(&xyz[i][2], 4);
        put(&s, 2);
    }
    for (const auto& poly : polygons) {
        const auto n = std::uint8_t(poly.size());
        if (ascii) {
            out += std::to_string(poly.size());
            for (const auto v : poly) out += " " + std::to_string(v);
            out += "\n";
            continue;
        }
        put(&n, 1);
        for (const auto v : poly) {
            if (index_type == "uint") {
                const auto u = std::uint32_t(v);
                put(&u, 4);
            } else {
                const auto k = std::int32_t(v);
                put(&k, 4);
            }
        }
    }
    return out;
}

}  // namespace

// Binary rows of fixed size and triangle lists are read in parallel (each row
// from its own offset); anything else falls back to the row-by-row reading.
// Either way: the same mesh, scalars, counts and first error as the ASCII file.
TEST(ReadMesh, BinaryPlyRowsReadInParallelEqualTheRowByRowReading)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    const std::size_t nv = 20000;
    std::vector<std::array<float, 3>> xyz(nv);
    for (auto& p : xyz) p = {u(rng), u(rng), u(rng)};
    std::uniform_int_distribution<std::int64_t> vertex(0, std::int64_t(nv) - 1);
    std::vector<std::vector<std::int64_t>> triangles(40000);
    for (auto& t : triangles) {
        do {
            t = {vertex(rng), vertex(rng), vertex(rng)};
        } while (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
    }
    struct Case
    {
        std::string name;
        std::vector<std::vector<std::int64_t>> polygons;
        std::string index_type = "int";
    };
    std::vector<Case> cases;
    cases.push_back({"triangles", triangles});
    cases.push_back({"uint", triangles, "uint"});
    cases.push_back({"quad", triangles});  // one quad in the middle: row by row
    cases.back().polygons[23456] = {1, 2, 3, 4};
    cases.push_back({"repeated", triangles});  // one triangle repeating a corner: dropped and counted
    cases.back().polygons[30001] = {5, 6, 5};
    cases.push_back({"unused", triangles});  // vertex 0 unused: renumbered
    for (auto& t : cases.back().polygons)
        for (auto& v : t)
            if (v == 0) v = 1;
    cases.back().polygons[0] = {2, 1, 3};
    for (const Case& c : cases) {
        const LoadedMesh ref = read_mesh(write_text(c.name + "_ascii.ply", ply_bytes("ascii", xyz, c.polygons, "int")));
        for (const std::string format : {"binary_little_endian", "binary_big_endian"}) {
            const LoadedMesh m =
                read_mesh(write_text(c.name + "_" + format + ".ply", ply_bytes(format, xyz, c.polygons, c.index_type)));
            EXPECT_EQ(m.mesh.points, ref.mesh.points) << c.name << " " << format;
            EXPECT_EQ(m.mesh.faces, ref.mesh.faces) << c.name << " " << format;
            ASSERT_EQ(m.vertex_scalars.size(), 2u);
            for (std::size_t k = 0; k < 2; ++k) {
                EXPECT_EQ(m.vertex_scalars[k].name, ref.vertex_scalars[k].name);
                EXPECT_EQ(m.vertex_scalars[k].values, ref.vertex_scalars[k].values) << c.name << " " << format;
            }
            EXPECT_EQ(m.input.file_faces, ref.input.file_faces);
            EXPECT_EQ(m.input.polygons_triangulated, ref.input.polygons_triangulated);
            EXPECT_EQ(m.input.repeated_index_faces, ref.input.repeated_index_faces);
            EXPECT_EQ(m.input.unreferenced_vertices, ref.input.unreferenced_vertices);
        }
    }
    EXPECT_EQ(read_mesh(write_text("q.ply", ply_bytes("binary_little_endian", xyz, cases[2].polygons, "int")))
                  .input.polygons_triangulated,
              1u);

    // The first bad index is named, whichever thread meets it first.
    auto bad = triangles;
    bad[31000] = {1, 2, std::int64_t(nv)};
    bad[9000] = {1, -4, 2};
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        const std::string msg = error_of<InvalidMeshError>(write_text("bad.ply", ply_bytes(format, xyz, bad, "int")));
        EXPECT_NE(msg.find("face 9000 refers to vertex -4"), std::string::npos) << format << ": " << msg;
    }
    // An unsigned index beyond an int: the row-by-row reader's error.
    auto huge = triangles;
    huge[12345] = {1, 2, 3000000000};
    const std::string h =
        error_of<IoError>(write_text("huge.ply", ply_bytes("binary_little_endian", xyz, huge, "uint")));
    EXPECT_NE(h.find("face 12345 has index 3000000000"), std::string::npos) << h;
}
