// Cross-check of meshdiff's jet curvature estimator (`--curvature jet`,
// issue 28) against CGAL's Monge_via_jet_fitting (CGAL 5.5, Debian
// libcgal-dev, header-only, with Eigen 3 for the SVD). Built only for
// reference/: see reference/cgal_jet.sh.
//
// Usage: cgal_jet MESH.ply
// Prints one line per vertex of MESH (in file order): the mean curvature
// H = -(k1 + k2) / 2 of CGAL's Monge form (d_fitting = 3, d_monge = 2) fitted
// to the vertex and its 2-ring (widened to the 3-ring when the 2-ring has
// fewer than 15 vertices, as meshdiff's jet does), "nan" where there is no
// fit (an unreferenced vertex, fewer than 10 points, a zero vertex normal or
// a non-finite result).
//
// Sign: CGAL orients the Monge normal arbitrarily (from the PCA frame). It is
// made to agree with the mesh's vertex normal (the sum of the cross products
// of its faces' edges, i.e. area-weighted face normals) by
// Monge_form::comply_wrt_given_normal, which flips n and the signs of k1, k2.
// In the Monge frame the surface is z = (k1 x^2 + k2 y^2) / 2 + ..., so a
// sphere with outward normals has k1, k2 < 0 and H = -(k1 + k2) / 2 = +1/r,
// meshdiff's convention.
//
// Differences from meshdiff's jet by construction: CGAL fits the full cubic
// (10 coefficients, with a constant term: the surface need not pass through
// the vertex), in the PCA frame of the points (not the vertex normal's),
// with all rows of weight 1 (meshdiff: interpolating, no constant term,
// vertex-normal frame, rows scaled by 1/|d|^4). meshdiff's cap of a 2-ring at
// 256 neighbours is not reproduced (no mesh of the study reaches it).
//
// The reader is a small PLY reader (ASCII or binary little-endian, any scalar
// vertex properties, one face list), so that the vertex order and count are
// exactly those of the file; polygons are fanned into triangles.
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Monge_fit = CGAL::Monge_via_jet_fitting<Kernel>;

namespace {

struct Property
{
    std::string name, type, count_type;  // count_type non-empty: a list
};

struct Element
{
    std::string name;
    std::size_t count = 0;
    std::vector<Property> props;
};

std::size_t type_size(const std::string& t)
{
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    throw std::runtime_error("unknown PLY type " + t);
}

double read_binary(const char* p, const std::string& t)
{
    auto get = [p](auto v) {
        std::memcpy(&v, p, sizeof v);
        return static_cast<double>(v);
    };
    if (t == "char" || t == "int8") return get(std::int8_t{});
    if (t == "uchar" || t == "uint8") return get(std::uint8_t{});
    if (t == "short" || t == "int16") return get(std::int16_t{});
    if (t == "ushort" || t == "uint16") return get(std::uint16_t{});
    if (t == "int" || t == "int32") return get(std::int32_t{});
    if (t == "uint" || t == "uint32") return get(std::uint32_t{});
    if (t == "float" || t == "float32") return get(float{});
    return get(double{});
}

void read_ply(const char* path, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& faces)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(std::string("cannot open ") + path);
    std::string line, format;
    std::vector<Element> elements;
    std::getline(in, line);
    if (line.rfind("ply", 0) != 0) throw std::runtime_error("not a PLY file");
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream w(line);
        std::string key;
        w >> key;
        if (key == "format") {
            w >> format;
        } else if (key == "element") {
            Element e;
            w >> e.name >> e.count;
            elements.push_back(e);
        } else if (key == "property") {
            Property p;
            w >> p.type;
            if (p.type == "list") {
                p.count_type = p.type;
                w >> p.count_type >> p.type;
            }
            w >> p.name;
            if (elements.empty()) throw std::runtime_error("property before element");
            elements.back().props.push_back(p);
        } else if (key == "end_header") {
            break;
        }
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian") throw std::runtime_error("PLY format " + format + " not supported");
    for (const Element& e : elements) {
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        int ix = -1, iy = -1, iz = -1, ilist = -1;
        for (std::size_t k = 0; k < e.props.size(); ++k) {
            const Property& p = e.props[k];
            if (p.name == "x") ix = static_cast<int>(k);
            if (p.name == "y") iy = static_cast<int>(k);
            if (p.name == "z") iz = static_cast<int>(k);
            if (!p.count_type.empty() && (p.name == "vertex_indices" || p.name == "vertex_index"))
                ilist = static_cast<int>(k);
        }
        if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) throw std::runtime_error("vertex without x, y, z");
        std::vector<double> scalars(e.props.size());
        std::vector<std::size_t> list;
        std::vector<char> buf(8);
        for (std::size_t i = 0; i < e.count; ++i) {
            for (std::size_t k = 0; k < e.props.size(); ++k) {
                const Property& p = e.props[k];
                if (p.count_type.empty()) {
                    if (ascii) {
                        in >> scalars[k];
                    } else {
                        in.read(buf.data(), static_cast<std::streamsize>(type_size(p.type)));
                        scalars[k] = read_binary(buf.data(), p.type);
                    }
                    continue;
                }
                double n = 0;
                if (ascii) {
                    in >> n;
                } else {
                    in.read(buf.data(), static_cast<std::streamsize>(type_size(p.count_type)));
                    n = read_binary(buf.data(), p.count_type);
                }
                if (static_cast<int>(k) == ilist) list.clear();
                for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
                    double v = 0;
                    if (ascii) {
                        in >> v;
                    } else {
                        in.read(buf.data(), static_cast<std::streamsize>(type_size(p.type)));
                        v = read_binary(buf.data(), p.type);
                    }
                    if (static_cast<int>(k) == ilist) list.push_back(static_cast<std::size_t>(v));
                }
            }
            if (!in) throw std::runtime_error("truncated PLY");
            if (is_vertex) points.emplace_back(scalars[ix], scalars[iy], scalars[iz]);
            if (is_face && ilist >= 0) faces.push_back(list);
        }
    }
    for (const auto& f : faces)
        for (std::size_t v : f)
            if (v >= points.size()) throw std::runtime_error("face index out of range");
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: cgal_jet MESH.ply\n";
        return 2;
    }
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    try {
        read_ply(argv[1], points, polygons);
    } catch (const std::exception& e) {
        std::cerr << "cgal_jet: " << argv[1] << ": " << e.what() << "\n";
        return 3;
    }
    const std::size_t n = points.size();
    std::vector<std::vector<std::size_t>> adj(n);
    std::vector<Vector> normal(n, Vector(0, 0, 0));
    for (const auto& poly : polygons) {
        for (std::size_t j = 1; j + 1 < poly.size(); ++j) {  // fan triangulation
            const std::size_t t[3] = {poly[0], poly[j], poly[j + 1]};
            const Vector fn = CGAL::cross_product(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
            for (int a = 0; a < 3; ++a) {
                normal[t[a]] = normal[t[a]] + fn;
                adj[t[a]].push_back(t[(a + 1) % 3]);
                adj[t[a]].push_back(t[(a + 2) % 3]);
            }
        }
    }
    for (auto& a : adj) {
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
    }
    constexpr std::size_t kMinNeighbors = 15;  // meshdiff's kJetMinNeighbors
    constexpr std::size_t kFitDegree = 3, kMongeDegree = 2, kCoefficients = 10;
    std::vector<int> ring(n, -1);  // ring number of the current vertex's BFS; reset after each vertex
    std::vector<std::size_t> visited;
    std::vector<Point> fit;
    std::size_t failed = 0, widened = 0;
    for (std::size_t v = 0; v < n; ++v) {
        // Rings by breadth-first search: the vertex, its 1-ring, 2-ring, and the 3-ring if needed.
        visited.assign(1, v);
        ring[v] = 0;
        std::size_t frontier_begin = 0;
        for (int r = 1; r <= 3; ++r) {
            if (r == 3) {
                if (visited.size() - 1 >= kMinNeighbors) break;
                ++widened;
            }
            const std::size_t frontier_end = visited.size();
            for (std::size_t i = frontier_begin; i < frontier_end; ++i)
                for (std::size_t w : adj[visited[i]])
                    if (ring[w] < 0) {
                        ring[w] = r;
                        visited.push_back(w);
                    }
            frontier_begin = frontier_end;
        }
        fit.clear();
        for (std::size_t w : visited) {
            fit.push_back(points[w]);  // visited[0] == v: CGAL's fit is at the first point
            ring[w] = -1;
        }
        double h = std::nan("");
        const double nn = std::sqrt(normal[v].squared_length());
        if (fit.size() >= kCoefficients && nn > 0) {
            Monge_fit monge_fit;
            Monge_fit::Monge_form form = monge_fit(fit.begin(), fit.end(), kFitDegree, kMongeDegree);
            form.comply_wrt_given_normal(normal[v] / nn);
            h = -(form.principal_curvatures(0) + form.principal_curvatures(1)) / 2;
        }
        if (!std::isfinite(h)) {
            h = std::nan("");
            ++failed;
        }
        std::printf("%.17g\n", h);
    }
    std::cerr << "cgal_jet: " << n << " vertices, " << widened << " widened to the 3-ring, " << failed
              << " without a fit\n";
    return 0;
}
