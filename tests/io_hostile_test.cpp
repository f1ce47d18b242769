// Hostile input (issue 13): malformed and extreme files must give one clear
// error naming the file, never a hang, a crash or a silently mangled mesh.
// The files are in tests/data/hostile/ (README.md there says what each is).
#include "meshdiff/io/io.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace meshdiff;
namespace fs = std::filesystem;

namespace {

std::string hostile(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/hostile/" + name;
}

fs::path temp_dir()
{
    const fs::path d = fs::temp_directory_path() / ("meshdiff_io_hostile_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

fs::path write_bytes(const std::string& name, const std::string& bytes)
{
    const fs::path p = temp_dir() / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

std::string bytes_of(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

enum class Kind
{
    Io,
    Invalid
};

// The message of the error reading \p path throws; fails the test if it
// throws nothing or the other kind.
std::string error_of(const std::string& path, Kind kind)
{
    try {
        read_mesh(path);
    } catch (const IoError& e) {
        EXPECT_EQ(kind, Kind::Io) << path << ": " << e.what();
        return e.what();
    } catch (const InvalidMeshError& e) {
        EXPECT_EQ(kind, Kind::Invalid) << path << ": " << e.what();
        return e.what();
    }
    ADD_FAILURE() << path << " read without an error";
    return "";
}

struct Case
{
    const char* file;
    Kind kind;
    const char* says;  // a part of the message
};

}  // namespace

TEST(ReadHostile, EveryFileGivesOneLineErrorNamingFileAndPlace)
{
    const Case cases[] = {
        {"off_header_only.off", Kind::Io, "no counts line"},
        {"off_negative_corner_count.off", Kind::Io, "line 6: face 0 has a negative corner count -3"},
        {"off_count_beyond_body.off", Kind::Io, "declares 2000000000 vertices, more than the 26 bytes"},
        {"off_inf.off", Kind::Invalid, "line 4: vertex 1 has a non-finite coordinate 'inf'"},
        {"off_overflow.off", Kind::Invalid, "vertex 1 has a non-finite coordinate '1e400'"},
        {"off_truncated.off", Kind::Io, "ends after 1 of the 2 faces"},
        {"off_trailing_face.off", Kind::Io, "line 7: data after the 1 faces"},
        {"off_4off.off", Kind::Io, "'4OFF' is an OFF variant meshdiff does not read"},
        {"off_negative_index.off", Kind::Invalid, "face 0 refers to vertex -1"},
        {"obj_empty_vertex_index.obj", Kind::Io, "line 4: '/1' is not a face corner"},
        {"obj_two_corners.obj", Kind::Invalid, "line 4: face 0 has 2 corners"},
        {"obj_zero_index.obj", Kind::Invalid, "vertex index 0"},
        {"obj_relative_before_first.obj", Kind::Invalid, "refers to vertex -4, but only 3 precede it"},
        {"obj_lines_and_points.obj", Kind::Invalid, "2 line and point elements (not surfaces)"},
        {"obj_beyond_limit.obj", Kind::Invalid, "line 2: vertex 2 has the coordinate '1e31' beyond meshdiff's limit"},
        {"stl_nan.stl", Kind::Invalid, "line 5: facet 0 corner 1 has a non-finite coordinate 'nan'"},
        {"stl_1e308.stl", Kind::Invalid, "coordinate '1e308' beyond meshdiff's limit of +-1e+30"},
        {"stl_nan_binary.stl", Kind::Invalid, "facet 0 corner 1 has a non-finite coordinate"},
        {"stl_count_mismatch.stl", Kind::Io, "declares 1000000 triangles (50000084 bytes) but the file has 134"},
        {"stl_truncated.stl", Kind::Io, "ends where a coordinate should follow"},
        {"ply_count_beyond_body.ply", Kind::Io, "declares 2147483648 'vertex' elements, more than the 3 bytes"},
        {"ply_duplicate_element.ply", Kind::Io, "two PLY elements named 'vertex'"},
        {"ply_trailing_face.ply", Kind::Io, "data after the last element"},
        {"ply_control_bytes.ply", Kind::Io, "'elem\\x1b[31m\\x0dent\\x01 vertex 3'"},
        {"ply_beyond_limit.ply", Kind::Invalid,
         "vertex 1 has the coordinate -2e+30 beyond meshdiff's limit of +-1e+30"},
    };
    for (const Case& c : cases) {
        const std::string msg = error_of(hostile(c.file), c.kind);
        EXPECT_NE(msg.find(c.file), std::string::npos) << msg;
        EXPECT_NE(msg.find(c.says), std::string::npos) << c.file << ": " << msg;
        EXPECT_EQ(msg.find_first_of("\n\r"), std::string::npos) << msg;
        for (const char ch : msg)
            EXPECT_TRUE(ch >= 0x20 && ch < 0x7f) << c.file << ": byte " << int(ch) << " in " << msg;
    }
}

TEST(ReadHostile, ValidVariantsRead)
{
    // Every OBJ corner form, relative indices, w and colours after x y z,
    // statements that are ignored (a missing mtllib is never opened), a line.
    const LoadedMesh obj = read_mesh(hostile("obj_all_corner_forms.obj"));
    EXPECT_EQ(obj.input.file_vertices, 4u);
    EXPECT_EQ(obj.input.file_faces, 3u);
    EXPECT_EQ(obj.input.polygons_triangulated, 1u);
    const std::vector<Face> want{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(obj.mesh.faces, want);

    // COFF with comments, a blank line, colours and a quad.
    const LoadedMesh coff = read_mesh(hostile("off_colours_comments.off"));
    EXPECT_EQ(coff.input.file_vertices, 5u);
    EXPECT_EQ(coff.input.file_faces, 2u);
    EXPECT_EQ(coff.input.unreferenced_vertices, 1u);
    EXPECT_EQ(coff.input.polygons_triangulated, 1u);
    EXPECT_EQ(coff.mesh.n_faces(), 3u);
    EXPECT_EQ(coff.mesh.points[2], Vec3(1, 1, 0));

    const LoadedMesh glued = read_mesh(hostile("off_glued_counts.off"));
    EXPECT_EQ(glued.mesh.n_vertices(), 4u);
    EXPECT_EQ(glued.mesh.n_faces(), 2u);

    // Two solids; the facet whose corners merge (1 and 1.0) is dropped and counted.
    const LoadedMesh stl = read_mesh(hostile("stl_two_solids.stl"));
    EXPECT_EQ(stl.input.file_faces, 3u);
    EXPECT_EQ(stl.input.repeated_index_faces, 1u);
    EXPECT_EQ(stl.mesh.n_vertices(), 4u);
    EXPECT_EQ(stl.mesh.n_faces(), 2u);

    // An element without properties holds no data, whatever its count.
    const LoadedMesh ply = read_mesh(hostile("ply_no_property_huge_count.ply"));
    EXPECT_EQ(ply.mesh.n_faces(), 1u);

    const LoadedMesh limit = read_mesh(hostile("ply_at_limit.ply"));
    EXPECT_EQ(limit.mesh.points[1].x(), -max_coordinate);
    EXPECT_EQ(limit.mesh.points[2].z(), max_coordinate);
}

TEST(ReadHostile, FloatFormatsRoundAsOpenMeshDid)
{
    // OBJ, OFF and ASCII STL coordinates are rounded once to float, as
    // OpenMesh's readers did, so that results on existing files stay the same.
    const auto obj = write_bytes("round.obj", "v 0.1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(read_mesh(obj).mesh.points[0].x(), double(0.1f));
    const auto off = write_bytes("round.off", "OFF\n3 1 0\n0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(read_mesh(off).mesh.points[0].x(), double(0.1f));
}

TEST(ReadHostile, NonRegularFilesAreRefusedBeforeOpening)
{
    const fs::path fifo = temp_dir() / "fifo.ply";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    EXPECT_NE(error_of(fifo.string(), Kind::Io).find("fifo.ply: not a regular file (a FIFO)"), std::string::npos);
    EXPECT_NE(error_of("/dev/null", Kind::Io).find("/dev/null: not a regular file (a character device)"),
              std::string::npos);
    const fs::path dir = temp_dir() / "dir.off";
    fs::create_directories(dir);
    EXPECT_NE(error_of(dir.string(), Kind::Io).find("dir.off: not a regular file (a directory)"), std::string::npos);

    // An OBJ whose mtllib names a FIFO: material files are never opened.
    const fs::path mtl = temp_dir() / "blocks.mtl";
    fs::remove(mtl);
    ASSERT_EQ(::mkfifo(mtl.c_str(), 0600), 0) << std::strerror(errno);
    const auto obj = write_bytes("mtl.obj", "mtllib blocks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    EXPECT_EQ(read_mesh(obj).mesh.n_faces(), 1u);
}

TEST(ReadHostile, BinaryDataAfterTheDeclaredElementsIsAnError)
{
    // Header counts that are too small: the same rule for every format.
    const std::string sphere = bytes_of(std::string(MESHDIFF_TEST_DATA_DIR) + "/sphere_ico_2562.ply");
    const std::string msg = error_of(write_bytes("longer.ply", sphere + "\x03\x01").string(), Kind::Io);
    EXPECT_NE(msg.find("2 bytes after the last element"), std::string::npos) << msg;

    std::string stl(80, ' ');
    const std::uint32_t n = 1;
    stl.append(reinterpret_cast<const char*>(&n), 4);
    const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    stl.append(reinterpret_cast<const char*>(tri), 48);
    stl.append(2, '\0');
    EXPECT_EQ(read_mesh(write_bytes("one.stl", stl)).mesh.n_faces(), 1u);
    const std::string s = error_of(write_bytes("longer.stl", stl + "xyz").string(), Kind::Io);
    EXPECT_NE(s.find("declares 1 triangles (134 bytes) but the file has 137"), std::string::npos) << s;
}
