#include "meshdiff/io.h"

#include "meshdiff/error.h"
#include "meshdiff/output_file.h"

#include "detail/ply_reader.h"

#include <fmt/format.h>
#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/exporter/ExporterT.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

namespace meshdiff {

namespace {

using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::Vec2f;
using OpenMesh::Vec3d;
using OpenMesh::Vec3f;
using OpenMesh::Vec3uc;
using OpenMesh::Vec4f;
using OpenMesh::Vec4uc;
using OpenMesh::VertexHandle;

// Collects the raw vertex and polygon lists from any OpenMesh reader, without
// building a halfedge structure (which would refuse non-manifold faces).
class SoupImporter : public OpenMesh::IO::BaseImporter
{
public:
    std::vector<Vec3> points;
    std::vector<std::vector<int>> polygons;

    VertexHandle add_vertex(const Vec3f& p) override
    {
        points.emplace_back(double(p[0]), double(p[1]), double(p[2]));
        return VertexHandle(int(points.size()) - 1);
    }
    VertexHandle add_vertex(const Vec3d& p) override
    {
        points.emplace_back(p[0], p[1], p[2]);
        return VertexHandle(int(points.size()) - 1);
    }
    VertexHandle add_vertex() override
    {
        points.emplace_back(0.0, 0.0, 0.0);
        return VertexHandle(int(points.size()) - 1);
    }
    HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
    FaceHandle add_face(const VHandles& idx) override
    {
        std::vector<int> poly;
        poly.reserve(idx.size());
        for (const auto& vh : idx) poly.push_back(vh.idx());
        polygons.push_back(std::move(poly));
        return FaceHandle(int(polygons.size()) - 1);
    }
    FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
    void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
    void set_face_texindex(FaceHandle, int) override {}
    void set_point(VertexHandle vh, const Vec3f& p) override
    {
        if (vh.idx() >= 0 && std::size_t(vh.idx()) < points.size())
            points[std::size_t(vh.idx())] = Vec3(double(p[0]), double(p[1]), double(p[2]));
    }
    void set_halfedge(VertexHandle, HalfedgeHandle) override {}
    void set_normal(VertexHandle, const Vec3f&) override {}
    void set_normal(VertexHandle, const Vec3d&) override {}
    void set_color(VertexHandle, const Vec3uc&) override {}
    void set_color(VertexHandle, const Vec4uc&) override {}
    void set_color(VertexHandle, const Vec3f&) override {}
    void set_color(VertexHandle, const Vec4f&) override {}
    void set_texcoord(VertexHandle, const Vec2f&) override {}
    void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_next(HalfedgeHandle, HalfedgeHandle) override {}
    void set_face(HalfedgeHandle, FaceHandle) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
    void set_texcoord(VertexHandle, const Vec3f&) override {}
    void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
    void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_color(EdgeHandle, const Vec3uc&) override {}
    void set_color(EdgeHandle, const Vec4uc&) override {}
    void set_color(EdgeHandle, const Vec3f&) override {}
    void set_color(EdgeHandle, const Vec4f&) override {}
    void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_normal(FaceHandle, const Vec3f&) override {}
    void set_normal(FaceHandle, const Vec3d&) override {}
    void set_color(FaceHandle, const Vec3uc&) override {}
    void set_color(FaceHandle, const Vec4uc&) override {}
    void set_color(FaceHandle, const Vec3f&) override {}
    void set_color(FaceHandle, const Vec4f&) override {}
    void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void add_texture_information(int, std::string) override {}
    bool is_triangle_mesh() const override { return false; }
    void reserve(unsigned int nv, unsigned int, unsigned int nf) override
    {
        // Header counts can be absurd in a corrupt file: cap the reservation.
        points.reserve(std::min<std::size_t>(nv, 1u << 26));
        polygons.reserve(std::min<std::size_t>(nf, 1u << 26));
    }
    size_t n_vertices() const override { return points.size(); }
    size_t n_faces() const override { return polygons.size(); }
    size_t n_edges() const override { return 0; }
};

std::string lower_extension(const std::filesystem::path& p)
{
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// OpenMesh's readers report problems on its own log streams; capture them so
// the one-line error can say why.
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

// True if an ASCII mesh file holds a "nan" or "inf" token: OpenMesh's text
// readers stop at one without saying why, so this names the real problem.
bool mentions_non_finite(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::string tok;
    while (in >> tok) {
        std::transform(tok.begin(), tok.end(), tok.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        const auto b = tok.find_first_not_of("+-");
        if (b == std::string::npos) continue;
        const std::string t = tok.substr(b);
        if (t == "nan" || t == "inf" || t == "infinity" || t.rfind("nan(", 0) == 0) return true;
    }
    return false;
}

}  // namespace

namespace {
LoadedMesh read_mesh_impl(const std::filesystem::path& path)
{
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw IoError(fmt::format("{}: no such file", name));
    if (std::filesystem::is_directory(path, ec))
        throw IoError(fmt::format("{}: is a directory, not a mesh file", name));
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) throw IoError(fmt::format("{}: cannot open for reading", name));
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size == 0) throw IoError(fmt::format("{}: file is empty", name));

    const std::string ext = lower_extension(path);
    if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".stl")
        throw IoError(fmt::format("{}: unknown mesh format '{}' (expected .ply, .obj, .off or .stl)", name, ext));

    SoupImporter importer;
    std::vector<VertexScalar> scalars;
    if (ext == ".ply") {
        // Our own reader: double precision and strict truncation checks.
        detail::PlySoup soup = detail::read_ply(name);
        importer.points = std::move(soup.points);
        importer.polygons = std::move(soup.polygons);
        for (std::size_t k = 0; k < soup.scalar_names.size(); ++k)
            scalars.push_back({soup.scalar_names[k], std::move(soup.scalar_values[k])});
    } else {
        bool ok = false;
        {
            CaptureOpenMeshLog quiet;
            OpenMesh::IO::Options opt;
            ok = OpenMesh::IO::IOManager().read(name, importer, opt);
        }
        if (!ok || importer.points.empty() || importer.polygons.empty()) {
            if (mentions_non_finite(path))
                throw InvalidMeshError(fmt::format("{}: the file has a non-finite coordinate (nan or inf)", name));
            if (!ok)
                throw IoError(
                    fmt::format("{}: could not parse the file as {} (corrupt or truncated?)", name, ext.substr(1)));
        }
    }

    LoadedMesh out;
    out.input.path = name;
    out.input.file_vertices = importer.points.size();
    out.input.file_faces = importer.polygons.size();
    if (importer.points.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no vertices", name));
    if (importer.polygons.empty()) throw InvalidMeshError(fmt::format("{}: mesh has no faces", name));

    const auto nv = std::int64_t(importer.points.size());
    for (std::size_t i = 0; i < importer.points.size(); ++i)
        if (!importer.points[i].allFinite())
            throw InvalidMeshError(fmt::format("{}: vertex {} has a non-finite coordinate ({}, {}, {})", name, i,
                                               importer.points[i].x(), importer.points[i].y(), importer.points[i].z()));

    // Triangulate, drop faces with a repeated corner, mark used vertices.
    std::vector<Face> faces;
    faces.reserve(importer.polygons.size());
    std::vector<std::int32_t> remap(importer.points.size(), -1);
    for (std::size_t f = 0; f < importer.polygons.size(); ++f) {
        const auto& poly = importer.polygons[f];
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
    out.mesh.points.reserve(std::size_t(next));
    for (std::size_t i = 0; i < remap.size(); ++i)
        if (remap[i] >= 0) out.mesh.points.push_back(importer.points[i]);
    for (auto& t : faces)
        for (auto& v : t) v = remap[std::size_t(v)];
    out.mesh.faces = std::move(faces);
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
    try {
        return read_mesh_impl(path);
    } catch (const Error&) {
        // OpenMesh's text readers stop at a "nan" token without saying so;
        // the symptoms (missing vertices, bad indices) hide the cause.
        const std::string ext = lower_extension(path);
        if ((ext == ".obj" || ext == ".off") && mentions_non_finite(path))
            throw InvalidMeshError(fmt::format("{}: the file has a non-finite coordinate (nan or inf)", path.string()));
        throw;
    }
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
