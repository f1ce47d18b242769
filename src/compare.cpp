#include "meshdiff/compare.h"

#include "meshdiff/error.h"

#include "core/release.h"
#include "distance/two_directions.h"
#include "roughness/local_roughness_closest.h"
#include "roughness/profile_keeping_h.h"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <functional>
#include <future>
#include <utility>

namespace meshdiff {

namespace {

// The facts of a point cloud: its points and box; no faces, no topology.
MeshFacts cloud_facts(const LoadedMesh& loaded)
{
    MeshFacts f;
    f.input = loaded.input;
    f.input.point_cloud = true;  // also for a faceless Mesh built in code
    f.topology.vertices = loaded.mesh.n_vertices();
    f.topology.components = 0;
    f.box = bounding_box(loaded.mesh);
    f.area = 0.0;
    return f;
}

// The options of the surface distance that \p o asks for, with the derived
// data \p a and \p b of the two meshes when given.
DistanceOptions distance_options(const CompareOptions& o, const MeshData* a = nullptr, const MeshData* b = nullptr)
{
    DistanceOptions d;
    d.data_a = a;
    d.data_b = b;
    d.sampling = o.sampling;
    d.hausdorff = o.hausdorff;
    d.summary = o.summary;
    d.vertex_distances = o.vertex_distances;
    d.keep_samples = o.keep_samples;
    d.index_a = o.index_original;
    d.index_b = o.index_processed;
    return d;
}

// The surface distance asked for in \p options; its per-vertex distances and
// kept samples moved to \p c's own.
void set_distance(Comparison& c, SurfaceDistance d)
{
    static_cast<VertexDistances&>(c) = std::exchange(static_cast<VertexDistances&>(d), {});
    c.forward_samples = std::exchange(d.forward_samples, {});
    c.backward_samples = std::exchange(d.backward_samples, {});
    c.distance = std::move(d);
}

// compare_meshes() when \p a or \p b is a point cloud (options checked).
Comparison compare_with_cloud(const LoadedMesh& a, const LoadedMesh& b, const CompareOptions& options)
{
    const bool cloud_a = is_point_cloud(a), cloud_b = is_point_cloud(b);
    const std::string which = cloud_a && cloud_b ? "both inputs are point clouds"
                              : cloud_a          ? "the original is a point cloud"
                                                 : "the processed input is a point cloud";
    if (!options.distance)
        throw InvalidArgumentError(
            fmt::format("compare: {} (no faces), so there is no roughness, and --no-distance switches off the surface "
                        "distance: nothing is left to compare",
                        which));
    Comparison c;
    c.options = options;
    if (options.roughness) c.roughness_unavailable = which + " (no faces): roughness needs faces on both sides";
    set_distance(c, cloud_surface_distance(a.mesh, b.mesh, distance_options(options)));
    c.same_connectivity_unavailable = which + " (no faces)";
    c.original = cloud_a ? cloud_facts(a) : mesh_facts(a);
    c.processed = cloud_b ? cloud_facts(b) : mesh_facts(b);
    return c;
}

// The local difference with metric levels: two indexes, one after the other.
template <typename IndexOf>
void local_with_radii(Comparison& c, const LoadedMesh& a, const MeshData& a_data, const LoadedMesh& b,
                      const MeshData& b_data, const CompareOptions& options, detail::HandedToDistance& handed,
                      const IndexOf& index_of)
{
    // The local difference (local_roughness.h): the ring levels and the global
    // level over the processed mesh's vertices and its own rings, against the
    // original surface (a level is each mesh's own L-ring, as in the
    // profiles); the radii over the original's vertices and balls, against the
    // processed surface (a radius is the same patch on both meshes, and the
    // original samples it densest).
    // The radii first: their index of the processed mesh is freed before the
    // original's is built for the ring levels and kept in \p handed.
    std::optional<LocalRoughnessDistance> on_original;
    if (!options.profile.radii.empty()) {
        LocalRoughnessParts radii;
        radii.levels = radii.global = false;
        std::optional<ClosestPointIndex> own;
        const ClosestPointIndex& index = index_of(options.index_processed, b_data, own, "processed");
        on_original = local_roughness_distance(a.mesh, *c.original_profile, b.mesh, *c.processed_profile, index,
                                               options.local_trim, false, radii);
    }
    LocalRoughnessParts rings;
    rings.radii = false;
    {
        const ClosestPointIndex& index = index_of(options.index_original, a_data, handed.index_a, "original");
        c.local_roughness = detail::local_roughness_distance(
            b.mesh, *c.processed_profile, a.mesh, *c.original_profile, index, options.local_trim,
            options.vertex_distances, rings, options.distance && options.hausdorff ? &handed.b_vertices_on_a : nullptr);
    }
    if (on_original) {
        c.local_roughness->radii = std::move(on_original->radii);
        c.local_roughness->rms_radii = std::move(on_original->rms_radii);
        c.local_roughness->vertices_radii = on_original->vertices_radii;
    }
}

// The two sigma profiles, their distance and, if asked for, the local
// difference (options checked). The index of the original the local
// difference builds, and the closest points of the processed mesh's vertices
// on it, are left in \p handed for the surface distance's backward direction.
void sigma_half(Comparison& c, const LoadedMesh& a, const MeshData& a_data, const LoadedMesh& b, const MeshData& b_data,
                const CompareOptions& options, detail::HandedToDistance& handed)
{
    // The local difference needs H per vertex, not D: the profiles keep H
    // only (their ring levels then fold D batch by batch, level_stream.h).
    const ProfileOptions& po = options.profile;
    auto frame_of = [&](const Mesh& mesh) {
        if (po.normalize != NormalizeMethod::Original) return normalization_of(mesh, po.normalize);
        Normalization frame = unit_normalization(a.mesh);
        frame.method = NormalizeMethod::Original;
        return frame;
    };
    validate(po);
    c.original_profile = detail::roughness_profile_keeping_H(a.mesh, po, frame_of(a.mesh), options.local);
    if (handed.release_incidences) handed.release_incidences();  // the profiles do not read them
    // An index the caller built is used (surface_distance() checks it too),
    // otherwise one of our own.
    auto index_of = [](const ClosestPointIndex* given, const MeshData& data, std::optional<ClosestPointIndex>& own,
                       const char* name) -> const ClosestPointIndex& {
        if (!given) return own.emplace(data);
        if (given->n_faces() != data.mesh().n_faces())
            throw InvalidArgumentError(fmt::format("CompareOptions: index_{0} is not an index of the {0} mesh", name));
        return *given;
    };
    std::vector<ClosestPoint>* closest = options.distance && options.hausdorff ? &handed.b_vertices_on_a : nullptr;
    if (options.local && po.radii.empty()) {
        // The local difference's ring levels (local_roughness.h) are over
        // the processed mesh's own rings: folded in its profile's ring
        // search (one search, not two), from the change of H at its vertices
        // against the original, whose index is built first for it.
        const ClosestPointIndex& index = index_of(options.index_original, a_data, handed.index_a, "original");
        detail::LocalRingsInProfile local(b.mesh, a.mesh, *c.original_profile, index, options.local_trim,
                                          options.vertex_distances, true, closest);
        c.processed_profile = detail::roughness_profile_keeping_H(
            b.mesh, po, frame_of(b.mesh), true,
            [&](const Mesh& unit, const std::vector<double>& H) { return local.start(unit, H, po.levels); });
        c.local_roughness = local.finish(*c.processed_profile);
    } else {
        c.processed_profile = detail::roughness_profile_keeping_H(b.mesh, po, frame_of(b.mesh), options.local);
    }
    c.roughness = roughness_distance(*c.original_profile, *c.processed_profile, options.k);
    if (options.local && !c.local_roughness) local_with_radii(c, a, a_data, b, b_data, options, handed, index_of);
    if (!options.profile.keep_vertex_data)
        for (RoughnessProfile* p : {&*c.original_profile, &*c.processed_profile}) {
            detail::release(p->H);
            detail::release(p->D);
            detail::release(p->D_global);
            detail::release(p->D_radii);
        }
}

}  // namespace

void validate(const CompareOptions& options)
{
    if (!options.roughness && !options.distance)
        throw OptionError("roughness", "both halves are switched off ({distance} too): nothing to compare");
    if (!(options.k > 0.0) || !std::isfinite(options.k))
        throw OptionError("k", fmt::format("{} must be finite and > 0", options.k));
    if (!is_known(options.measure)) throw OptionError("measure", "not a known roughness measure");
    if (options.corsini_unbiased && options.measure != RoughnessMeasure::Corsini)
        throw OptionError("corsini_unbiased", "needs {measure} corsini");
    if (options.measure == RoughnessMeasure::Corsini && options.profile.normalize != NormalizeMethod::Paper)
        throw OptionError("profile.normalize", "the dihedral angles of {measure} corsini do not depend on a scaling");
    if (!(options.local_trim >= 0.0 && options.local_trim <= kMaxTrim))
        throw OptionError("local_trim", fmt::format("{} is not a share in [0, {}]", options.local_trim, kMaxTrim));
    if (options.measure == RoughnessMeasure::Corsini && options.profile.trim > 0.0)
        throw OptionError("profile.trim", "trims sigma and the local difference, not {measure} corsini");
    if (options.measure == RoughnessMeasure::Corsini && !options.profile.radii.empty())
        throw OptionError("profile.radii", "metric levels are not defined for {measure} corsini");
    validate(options.profile);
    validate(options.sampling);
    if (options.hausdorff) validate(*options.hausdorff);
    validate(options.summary);
}

Comparison compare_meshes(const LoadedMesh& a, const LoadedMesh& b, const CompareOptions& options)
{
    validate(options);
    const ProgressScope scope(options.progress ? options.progress : current_progress());
    check_cancelled(current_progress());
    if (is_point_cloud(a) || is_point_cloud(b)) return compare_with_cloud(a, b, options);
    Comparison c;
    c.options = options;
    c.options.progress = nullptr;
    c.options.index_original = c.options.index_processed = nullptr;  // not kept beyond the call
    // What every stage derives from a mesh (box, degenerate faces, vertex-face
    // incidence, validation), derived once per mesh (mesh_data.h).
    const MeshData a_data(a.mesh), b_data(b.mesh);
    // The serial topology reports overlap the (partly serial) analyses, on
    // threads of their own unless OpenMP is limited to one thread.
    const auto policy = omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred;
    // They stop too when the Progress says so.
    Progress* progress = current_progress();
    auto facts_of = [progress](const LoadedMesh& m, const MeshData& data) {
        const ProgressScope in_this_thread(progress);
        return mesh_facts(m, data);
    };
    auto facts_a = std::async(policy, facts_of, std::cref(a), std::cref(a_data));
    auto facts_b = std::async(policy, facts_of, std::cref(b), std::cref(b_data));
    if (options.roughness && options.measure == RoughnessMeasure::Corsini) {
        CorsiniOptions co;
        co.levels = options.profile.levels;
        co.global = options.profile.global;
        co.unbiased = options.corsini_unbiased;
        c.original_corsini = corsini_profile(a.mesh, co);
        c.processed_corsini = corsini_profile(b.mesh, co);
        c.corsini = corsini_distance(*c.original_corsini, *c.processed_corsini, options.k);
    }
    // The original's index and the closest points of the processed mesh's
    // vertices on it, found once: by the local difference (when asked for),
    // and handed to the distances to the original.
    detail::HandedToDistance handed;
    // The vertex-face incidences (28 MB a mesh of 2M faces) are read at the
    // start of stages only (the topology reports, the sample plans, the
    // pseudo-normals): freed once the reports are done and after each
    // direction's start, derived again by the next (8 ms for 2M faces).
    handed.release_incidences = [&] {
        facts_a.wait();
        facts_b.wait();
        detail::release_vertex_faces(a_data);
        detail::release_vertex_faces(b_data);
    };
    if (options.roughness && options.measure != RoughnessMeasure::Corsini)
        sigma_half(c, a, a_data, b, b_data, options, handed);
    if (options.distance) {
        set_distance(
            c, detail::two_directions(a.mesh, b.mesh, distance_options(options, &a_data, &b_data), options.keep_samples,
                                      options.keep_samples, false, detail::kSampleChunk, &handed));
    } else if (options.vertex_distances) {
        if (!handed.index_a) handed.index_a.emplace(a_data);
        c.processed_vertex_distance =
            vertex_distances(b.mesh, a.mesh, *handed.index_a, c.processed_vertex_signed_distance);
        handed.index_a.reset();
        c.original_vertex_distance =
            vertex_distances(a.mesh, b.mesh, ClosestPointIndex(b_data), c.original_vertex_signed_distance);
    }
    c.same_connectivity = same_connectivity(a_data, b_data, &c.same_connectivity_unavailable);
    c.original = facts_a.get();
    c.processed = facts_b.get();
    return c;
}

}  // namespace meshdiff
