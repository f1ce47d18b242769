#include "meshdiff/io/io.h"

#include "meshdiff/error.h"
#include "meshdiff/io/output_file.h"

#include "io/readers/ply_reader.h"
#include "io/readers/read_util.h"
#include "io/readers/readers.h"

#include <fmt/format.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/exporter/ExporterT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

namespace meshdiff {

namespace {

std::string lower_extension(const std::filesystem::path& p)
{
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// OpenMesh's writers report problems on its own log streams; keep them quiet,
// the one-line error says what failed.
class CaptureOpenMeshLog
{
public:
    CaptureOpenMeshLog()
    {
        omerr().disable();
        omlog().disable();
        omout().disable();
    }
    ~CaptureOpenMeshLog()
    {
        omerr().enable();
        omlog().enable();
        omout().enable();
    }
    CaptureOpenMeshLog(const CaptureOpenMeshLog&) = delete;
    CaptureOpenMeshLog& operator=(const CaptureOpenMeshLog&) = delete;
};

// "a FIFO" and so on, for the message refusing a file that is not regular.
const char* file_kind(std::filesystem::file_type t)
{
    using std::filesystem::file_type;
    switch (t) {
        case file_type::directory:
            return "a directory";
        case file_type::fifo:
            return "a FIFO";
        case file_type::character:
            return "a character device";
        case file_type::block:
            return "a block device";
        case file_type::socket:
            return "a socket";
        default:
            return "of an unknown kind";
    }
}

}  // namespace

namespace {

// read_mesh() and read_mesh_or_cloud(): with \p allow_cloud, a file with
// vertices and no faces is a point cloud.
// A list of triangles only (a reader's uniform list), every corner in
// [0, nv) and no triangle repeating one: \p faces gets them, in parallel.
// Otherwise false and \p faces stays empty: the loop of read_any() reports
// the first bad face and drops the others, in order, as for any list.
bool fine_triangles(const detail::PolygonList& polygons, std::int64_t nv, std::vector<Face>& faces)
{
    if (polygons.uniform() != 3) return false;
    const auto n = std::int64_t(polygons.size());
    bool fine = true;
#pragma omp parallel for schedule(static) reduction(&& : fine)
    for (std::int64_t f = 0; f < n; ++f) {
        const auto t = polygons[std::size_t(f)];
        const int a = t[0], b = t[1], c = t[2];
        if (a < 0 || a >= nv || b < 0 || b >= nv || c < 0 || c >= nv || a == b || b == c || a == c) fine = false;
    }
    if (!fine || n == 0) return false;
    faces.resize(std::size_t(n));
#pragma omp parallel for schedule(static)
    for (std::int64_t f = 0; f < n; ++f) {
        const auto t = polygons[std::size_t(f)];
        faces[std::size_t(f)] = {t[0], t[1], t[2]};
    }
    return true;
}

LoadedMesh read_any(const std::filesystem::path& path, bool allow_cloud)
{
    const std::string name = path.string();
    // The kind of file first, without opening it: opening a FIFO would block.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) throw IoError(fmt::format("{}: no such file", name));
    if (ec) throw IoError(fmt::format("{}: cannot access ({})", name, ec.message()));
    if (status.type() != std::filesystem::file_type::regular)
        throw IoError(fmt::format("{}: not a regular file ({})", name, file_kind(status.type())));
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) throw IoError(fmt::format("{}: cannot open for reading", name));
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size == 0) throw IoError(fmt::format("{}: file is empty", name));

    const std::string ext = lower_extension(path);
    if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".stl")
        throw IoError(
            fmt::format("{}: unknown mesh format {} (expected .ply, .obj, .off or .stl)", name, detail::quote(ext)));

    // meshdiff's own strict readers (OpenMesh's loop forever or abort on
    // malformed files, issue 13).
    detail::Soup soup;
    std::vector<VertexScalar> scalars;
    if (ext == ".ply") {
        detail::PlySoup ply = detail::read_ply(name);
        soup.points = std::move(ply.points);
        soup.polygons = std::move(ply.polygons);
        for (std::size_t k = 0; k < ply.scalar_names.size(); ++k)
            scalars.push_back({ply.scalar_names[k], std::move(ply.scalar_values[k])});
    } else if (ext == ".off") {
        soup = detail::read_off(name);
    } else if (ext == ".obj") {
        soup = detail::read_obj(name);
    } else {
        soup = detail::read_stl(name);
    }

    LoadedMesh out;
    out.input.path = name;
    out.input.file_vertices = soup.points.size();
    out.input.file_faces = soup.polygons.size();
    if (soup.points.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no vertices", name));
    if (soup.polygons.empty() && !allow_cloud)
        throw InvalidMeshError(
            fmt::format("{}: mesh has no faces: a point cloud ({} vertices); only compare accepts point clouds", name,
                        soup.points.size()));

    const auto nv = std::int64_t(soup.points.size());
    for (std::size_t i = 0; i < soup.points.size(); ++i) {
        const Vec3& p = soup.points[i];
        if (!p.allFinite())
            throw InvalidMeshError(
                fmt::format("{}: vertex {} has a non-finite coordinate ({}, {}, {})", name, i, p.x(), p.y(), p.z()));
        for (int k = 0; k < 3; ++k)
            if (std::abs(p[k]) > max_coordinate)
                throw InvalidMeshError(
                    fmt::format("{}: vertex {} has the coordinate {} beyond meshdiff's limit of +-{}", name, i, p[k],
                                max_coordinate));
    }

    if (soup.polygons.empty()) {  // a point cloud: every point is kept
        out.input.point_cloud = true;
        out.mesh.points = std::move(soup.points);
        out.vertex_scalars = std::move(scalars);
        return out;
    }

    // Triangulate, drop faces with a repeated corner, mark used vertices.
    std::vector<Face> faces;
    std::vector<std::int32_t> remap(soup.points.size(), -1);
    const bool all_fine = fine_triangles(soup.polygons, nv, faces);
    if (all_fine) {
        for (const Face& t : faces)
            for (auto v : t) remap[std::size_t(v)] = 0;
    } else {
        faces.reserve(soup.polygons.size());
    }
    for (std::size_t f = all_fine ? soup.polygons.size() : 0; f < soup.polygons.size(); ++f) {
        const auto& poly = soup.polygons[f];
        if (poly.size() < 3) throw InvalidMeshError(fmt::format("{}: face {} has {} corners", name, f, poly.size()));
        for (int v : poly)
            if (v < 0 || v >= nv)
                throw InvalidMeshError(
                    fmt::format("{}: face {} refers to vertex {}, but there are {} vertices", name, f, v, nv));
        if (poly.size() > 3) ++out.input.polygons_triangulated;
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
            Face t{poly[0], poly[k], poly[k + 1]};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
                ++out.input.repeated_index_faces;
                continue;
            }
            for (auto v : t) remap[std::size_t(v)] = 0;
            faces.push_back(t);
        }
    }
    if (faces.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no faces with three distinct corners", name));

    std::int32_t next = 0;
    for (std::size_t i = 0; i < remap.size(); ++i)
        if (remap[i] == 0) remap[i] = next++;
    out.input.unreferenced_vertices = remap.size() - std::size_t(next);
    out.mesh.faces = std::move(faces);
    if (out.input.unreferenced_vertices == 0) {
        // Every vertex is used: the numbering stays, nothing is copied.
        out.mesh.points = std::move(soup.points);
        out.vertex_scalars = std::move(scalars);
        return out;
    }
    out.mesh.points.reserve(std::size_t(next));
    for (std::size_t i = 0; i < remap.size(); ++i)
        if (remap[i] >= 0) out.mesh.points.push_back(soup.points[i]);
    for (auto& t : out.mesh.faces)
        for (auto& v : t) v = remap[std::size_t(v)];
    for (auto& sc : scalars) {
        VertexScalar kept{sc.name, {}};
        kept.values.reserve(out.mesh.points.size());
        for (std::size_t i = 0; i < remap.size(); ++i)
            if (remap[i] >= 0) kept.values.push_back(sc.values[i]);
        out.vertex_scalars.push_back(std::move(kept));
    }
    return out;
}

}  // namespace

LoadedMesh read_mesh(const std::filesystem::path& path)
{
    return read_any(path, false);
}

LoadedMesh read_mesh_or_cloud(const std::filesystem::path& path)
{
    return read_any(path, true);
}

bool is_point_cloud(const LoadedMesh& loaded)
{
    return loaded.mesh.faces.empty();
}

const VertexScalar& vertex_scalar(const LoadedMesh& loaded, const std::string& name)
{
    for (const auto& s : loaded.vertex_scalars)
        if (s.name == name) return s;
    throw InvalidArgumentError(fmt::format("{} has no vertex property '{}'", loaded.input.path, name));
}

void write_ply(const std::filesystem::path& path, const Mesh& mesh, const std::vector<VertexScalar>& scalars,
               const std::vector<std::array<std::uint8_t, 3>>& colors, const std::vector<std::string>& comments)
{
    for (const auto& s : scalars)
        if (s.values.size() != mesh.n_vertices())
            throw InvalidArgumentError(fmt::format("write_ply: property '{}' has {} values for {} vertices", s.name,
                                                   s.values.size(), mesh.n_vertices()));
    if (!colors.empty() && colors.size() != mesh.n_vertices())
        throw InvalidArgumentError(
            fmt::format("write_ply: {} colours for {} vertices", colors.size(), mesh.n_vertices()));

    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw IoError(fmt::format("{}: cannot open for writing", path.string()));
        out << "ply\nformat binary_little_endian 1.0\ncomment written by meshdiff\n";
        for (std::string c : comments) {
            // A comment is one header line: a line break (from a file name, say) would end it.
            std::replace_if(
                c.begin(), c.end(), [](char ch) { return ch == '\n' || ch == '\r'; }, ' ');
            out << "comment " << c << "\n";
        }
        out << "element vertex " << mesh.n_vertices() << "\n";
        out << "property double x\nproperty double y\nproperty double z\n";
        for (const auto& s : scalars) out << "property double " << s.name << "\n";
        if (!colors.empty()) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
        out << "element face " << mesh.n_faces() << "\n";
        out << "property list uchar int vertex_indices\nend_header\n";

        static_assert(sizeof(double) == 8 && sizeof(std::int32_t) == 4, "PLY types");
        const std::size_t stride = 24 + 8 * scalars.size() + (colors.empty() ? 0 : 3);
        std::vector<char> buf(stride * mesh.n_vertices());
        char* p = buf.data();
        for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
            std::memcpy(p, mesh.points[i].data(), 24);
            p += 24;
            for (const auto& s : scalars) {
                std::memcpy(p, &s.values[i], 8);
                p += 8;
            }
            if (!colors.empty()) {
                std::memcpy(p, colors[i].data(), 3);
                p += 3;
            }
        }
        out.write(buf.data(), std::streamsize(buf.size()));
        std::vector<char> fbuf(13 * mesh.n_faces());
        p = fbuf.data();
        for (const Face& t : mesh.faces) {
            *p++ = 3;
            std::memcpy(p, t.data(), 12);
            p += 12;
        }
        out.write(fbuf.data(), std::streamsize(fbuf.size()));
        out.close();
        if (!out) throw IoError(fmt::format("{}: write failed", path.string()));
    });
}

bool writes_vertex_properties(const std::filesystem::path& path)
{
    return lower_extension(path) == ".ply";
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const std::vector<VertexScalar>& scalars,
                const std::vector<std::string>& comments)
{
    const std::string ext = lower_extension(path);
    if (ext == ".ply") return write_ply(path, mesh, scalars, {}, comments);
    if (ext != ".obj" && ext != ".off" && ext != ".stl")
        throw IoError(
            fmt::format("{}: unknown mesh format '{}' (expected .ply, .obj, .off or .stl)", path.string(), ext));
    OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble> om;
    std::vector<OpenMesh::VertexHandle> vh;
    vh.reserve(mesh.n_vertices());
    for (const auto& p : mesh.points) vh.push_back(om.add_vertex(OpenMesh::Vec3d(p.x(), p.y(), p.z())));
    bool ok = true;
    {
        CaptureOpenMeshLog quiet;
        for (const Face& t : mesh.faces) {
            auto fh = om.add_face(vh[std::size_t(t[0])], vh[std::size_t(t[1])], vh[std::size_t(t[2])]);
            if (!fh.is_valid()) ok = false;
        }
    }
    if (!ok)
        throw IoError(fmt::format("{}: could not write (non-manifold faces cannot be written as {}; use .ply)",
                                  path.string(), ext.substr(1)));
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        bool written = false;
        {
            CaptureOpenMeshLog quiet;
            written = OpenMesh::IO::write_mesh(om, tmp.string(), OpenMesh::IO::Options::Default, 17);
        }
        if (!written) throw IoError(fmt::format("{}: could not write", path.string()));
    });
}

}  // namespace meshdiff
