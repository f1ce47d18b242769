#include "meshdiff/geometry/cotangent.h"

#include "core/face_corner.h"

#include <utility>

namespace meshdiff {

using detail::corner_of;

CotangentSums cotangent_sums(const Mesh& mesh, const Adjacency& vf, const std::vector<Vec3>& p, std::size_t i)
{
    CotangentSums c;
    double area = 0.0;
    for (auto f = vf.begin(i); f != vf.end(i); ++f) {
        const Face& t = mesh.faces[*f];
        const int k = corner_of(t, i);
        if (k == 3) continue;
        const Vec3& xi = p[i];
        const Vec3& xj = p[std::size_t(t[std::size_t((k + 1) % 3)])];
        const Vec3& xk = p[std::size_t(t[std::size_t((k + 2) % 3)])];
        const Vec3 eij = xj - xi, eik = xk - xi, ejk = xk - xj;
        const double cot_j = cot(-eij, ejk);   // angle at j, opposite edge (i, k)
        const double cot_k = cot(-eik, -ejk);  // angle at k, opposite edge (i, j)
        c.sum += cot_k * eij + cot_j * eik;
        c.abs_weights += std::abs(cot_j) + std::abs(cot_k);
        area += mixed_area_part(eij, eik, ejk, cot_j, cot_k);
    }
    c.area4 = area > 0 ? 4 * area : 0.0;
    return c;
}

std::vector<CotangentSums> cotangent_sums_by_face(const Mesh& mesh, const std::vector<char>& skip_face)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<CotangentSums> c(n);
    std::vector<double> area(n, 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        if (!skip_face.empty() && skip_face[f]) continue;
        const Face& t = mesh.faces[f];
        const Vec3* x[3] = {&mesh.points[std::size_t(t[0])], &mesh.points[std::size_t(t[1])],
                            &mesh.points[std::size_t(t[2])]};
        const double tri = 0.5 * (*x[1] - *x[0]).cross(*x[2] - *x[0]).norm();
        // The cotangent of each corner once: at corner k between the edges to k+1 and k+2.
        double cots[3];
        for (int k = 0; k < 3; ++k) cots[k] = cot(*x[(k + 1) % 3] - *x[k], *x[(k + 2) % 3] - *x[k]);
        for (int k = 0; k < 3; ++k) {
            const int j = (k + 1) % 3, l = (k + 2) % 3;
            const Vec3 eij = *x[j] - *x[k], eil = *x[l] - *x[k], ejl = *x[l] - *x[j];
            CotangentSums& s = c[std::size_t(t[std::size_t(k)])];
            s.sum += cots[l] * eij + cots[j] * eil;
            s.abs_weights += std::abs(cots[j]) + std::abs(cots[l]);
            area[std::size_t(t[std::size_t(k)])] += mixed_area_part(eij, eil, ejl, cots[j], cots[l], tri);
        }
    }
    for (std::size_t i = 0; i < n; ++i) c[i].area4 = area[i] > 0 ? 4 * area[i] : 0.0;
    return c;
}

Vec3 curvature_normal(const Mesh& mesh, const Adjacency& vf, const std::vector<Vec3>& p, std::size_t i)
{
    return cotangent_sums(mesh, vf, p, i).curvature_normal();
}

CotangentSystem backward_euler_system(const Mesh& mesh, const Adjacency& vf, const std::vector<char>& fixed, double dt,
                                      const std::vector<Vec3>& p)
{
    const std::size_t n = p.size();
    // Vertices without mixed area are held too. The area is summed here with
    // the third edge taken as eil - eij (not x_l - x_j as in cotangent_sums()):
    // the same quantity, kept in this rounding so that implicit smoothing
    // gives bitwise the results it gave before this module existed.
    std::vector<double> area4(n, 0.0);
    std::vector<char> held(fixed);
    for (std::size_t i = 0; i < n; ++i) {
        if (held[i]) continue;
        double area = 0.0;
        for (auto f = vf.begin(i); f != vf.end(i); ++f) {
            const Face& tri = mesh.faces[*f];
            const int k = corner_of(tri, i);
            if (k == 3) continue;
            const Vec3 eij = p[std::size_t(tri[std::size_t((k + 1) % 3)])] - p[i];
            const Vec3 eil = p[std::size_t(tri[std::size_t((k + 2) % 3)])] - p[i];
            const Vec3 ejl = eil - eij;
            area += mixed_area_part(eij, eil, ejl, cot(-eij, ejl), cot(-eil, -ejl));
        }
        if (area > 0)
            area4[i] = 4 * area;
        else
            held[i] = 1;
    }
    CotangentSystem s;
    s.index.assign(n, -1);
    Eigen::Index free = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!held[i]) s.index[i] = free++;
    s.rhs.resize(free, 3);
    s.positions.resize(free, 3);
    s.matrix.resize(free, free);
    if (free == 0) return s;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(7 * std::size_t(free));
    for (std::size_t i = 0; i < n; ++i) {
        if (held[i]) continue;
        const Eigen::Index row = s.index[i];
        s.positions.row(row) = p[i].transpose();
        s.rhs.row(row) = area4[i] * p[i].transpose();
        double diagonal = area4[i];
        for (auto f = vf.begin(i); f != vf.end(i); ++f) {
            const Face& tri = mesh.faces[*f];
            const int k = corner_of(tri, i);
            if (k == 3) continue;
            const auto j = std::size_t(tri[std::size_t((k + 1) % 3)]);
            const auto l = std::size_t(tri[std::size_t((k + 2) % 3)]);
            const Vec3 eij = p[j] - p[i], eil = p[l] - p[i], ejl = p[l] - p[j];
            // Edge (i, j) is opposite the corner at l, edge (i, l) opposite the corner at j.
            for (const auto& [v, w] : {std::pair{j, cot(-eil, -ejl)}, std::pair{l, cot(-eij, ejl)}}) {
                diagonal += dt * w;
                if (held[v])
                    s.rhs.row(row) += dt * w * p[v].transpose();
                else
                    t.emplace_back(row, s.index[v], -dt * w);
            }
        }
        t.emplace_back(row, row, diagonal);
    }
    s.matrix.setFromTriplets(t.begin(), t.end());
    return s;
}

}  // namespace meshdiff
