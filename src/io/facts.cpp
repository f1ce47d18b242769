#include "meshdiff/io/facts.h"

// The profile's warnings read the roughness profile: the one arrow from io/
// up to roughness/ (the header only declares the type).
#include "meshdiff/roughness/roughness.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace meshdiff {

MeshFacts mesh_facts(const LoadedMesh& loaded)
{
    return mesh_facts(loaded, MeshData(loaded.mesh));
}

MeshFacts mesh_facts(const LoadedMesh& loaded, const MeshData& data)
{
    MeshFacts f;
    f.input = loaded.input;
    f.topology = topology_report(data);
    f.box = data.box();
    f.area = surface_area(loaded.mesh);
    return f;
}

std::vector<Warning> warnings(const MeshFacts& f, const RoughnessProfile* p)
{
    std::vector<Warning> w;
    auto add = [&w](WarningKind kind, double value, std::string text, int level = -1) {
        w.push_back({kind, level, value, std::move(text)});
    };
    const auto& t = f.topology;
    if (f.input.unreferenced_vertices)
        add(WarningKind::UnreferencedVertices, double(f.input.unreferenced_vertices),
            fmt::format("{} unreferenced vertices were dropped", f.input.unreferenced_vertices));
    if (f.input.repeated_index_faces)
        add(WarningKind::RepeatedCornerFaces, double(f.input.repeated_index_faces),
            fmt::format("{} faces with a repeated corner were dropped", f.input.repeated_index_faces));
    if (t.isolated_vertices)
        add(WarningKind::IsolatedVertices, double(t.isolated_vertices),
            fmt::format("{} vertices are in no face (their curvature is undefined)", t.isolated_vertices));
    if (t.non_manifold_edges || t.non_manifold_vertices)
        add(WarningKind::NonManifold, double(t.non_manifold_edges),
            fmt::format("non-manifold: {} edges, {} vertices", t.non_manifold_edges, t.non_manifold_vertices));
    if (t.orientation_conflicts)
        add(WarningKind::OrientationConflicts, double(t.orientation_conflicts),
            fmt::format("inconsistent orientation on {} edges: curvature signs near them cannot be trusted",
                        t.orientation_conflicts));
    if (t.degenerate_faces)
        add(WarningKind::DegenerateFaces, double(t.degenerate_faces),
            fmt::format("{} zero-area faces (no normal, no samples)", t.degenerate_faces));
    if (t.duplicate_faces)
        add(WarningKind::DuplicateFaces, double(t.duplicate_faces),
            fmt::format("{} duplicate faces", t.duplicate_faces));
    if (t.boundary_edges)
        add(WarningKind::OpenSurface, double(t.boundary_edges),
            fmt::format("open surface: {} boundary edges in {} loops", t.boundary_edges, t.boundary_loops));
    if (t.components > 1)
        add(WarningKind::Components, double(t.components),
            fmt::format("{} connected components: ring levels stay inside a component, the global level "
                        "spans all",
                        t.components));
    if (p) {
        if (p->curvature_undefined)
            add(WarningKind::UndefinedCurvature, double(p->curvature_undefined),
                fmt::format("{} vertices have undefined curvature and are left out", p->curvature_undefined));
        if (p->curvature_steep) {
            const double fits = double(f.topology.vertices) - double(p->curvature_undefined);
            const double share = fits > 0.0 ? double(p->curvature_steep) / fits : 0.0;
            if (share > kJetSteepShare)
                add(WarningKind::SteepFits, share,
                    fmt::format("{:.0f}% of the jet fits tilt more than 30 degrees from the vertex normal: the "
                                "surface is rough at the scale of its edges, where the jet's H stops growing with "
                                "the roughness (sigma saturates; --curvature goldfeather does not)",
                                100.0 * share));
        }
        if (p->curvature_capped)
            add(WarningKind::CappedNeighbourhoods, double(p->curvature_capped),
                fmt::format("{} curvature fits beside a vertex of very high valence used a capped 2-ring (the "
                            "1-ring and the nearest others, {} in all; vertices {}{})",
                            p->curvature_capped, kMaxFitNeighbors, fmt::join(p->curvature_capped_vertices, ", "),
                            p->curvature_capped > p->curvature_capped_vertices.size() ? ", ..." : ""));
        auto check = [&](const LevelRoughness& l, const std::string& name, int level) {
            if (l.top_share > 0.5) {
                add(WarningKind::OutliersDominate, l.top_share,
                    fmt::format("{}: the worst {:.1f}% of vertices make {:.0f}% of sigma^2 (outliers "
                                "dominate; see worst_vertices)",
                                name, 100.0 * p->outlier_fraction, 100.0 * l.top_share),
                    level);
                w.back().radius = l.radius;
            }
            if (l.vertices_used == 0) {
                add(WarningKind::NoDefinedD, 0.0,
                    fmt::format("{}: no vertex has a defined D, so no sigma (null, '-'; no d_L either)", name), level);
                w.back().radius = l.radius;
                return;
            }
            // A share of the vertices with curvature but no neighbourhood:
            // sigma then speaks for the others only.
            const std::size_t with_h = l.vertices_used + l.no_neighborhood;
            const double share = with_h ? double(l.no_neighborhood) / double(with_h) : 0.0;
            if (share > kSparseNeighbourhoodShare) {
                add(WarningKind::SparseNeighbourhoods, share,
                    fmt::format("{}: {:.0f}% of the vertices have no neighbourhood; sigma is of the other {}", name,
                                100.0 * share, l.vertices_used),
                    level);
                w.back().radius = l.radius;
            }
        };
        for (const auto& l : p->levels) check(l, fmt::format("level {}", l.level), l.level);
        if (p->has_global) check(p->global, "global level", p->global.level);
        // Metric levels: only when asked for, so reports without them are unchanged.
        for (const auto& l : p->radii)
            check(l, fmt::format("radius {:g}", l.radius) + (l.vertices_used == 0 ? " (below the edge length?)" : ""),
                  -1);
    }
    return w;
}

}  // namespace meshdiff
