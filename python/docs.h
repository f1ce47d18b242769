//! \file docs.h
//! \brief The docstrings of the Python module `meshdiff` (module.cpp binds them):
//! the module's, one per function, the option lists that compare(),
//! compare_files(), profile() and profile_file() append to theirs, and those of
//! DistanceIndex and its members. help(meshdiff) shows them as written here.
#pragma once

namespace meshdiff::python {

//! The module's docstring: what meshdiff computes, the array conventions, the errors.
constexpr const char* kModuleDoc = R"doc(meshdiff: how a processed triangle mesh differs from its original.

Roughness profiles after Kushunapally, Razdan & Bridges 2007 (per-vertex mean
curvature H, its deviation D_L from the mean over the L-ring, sigma_L =
RMS(D_L)), the per-level roughness distance d_L, and Metro-style surface
distances, on numpy arrays or mesh files. The full reference is docs/python.md.

Meshes are V, F: V an (n, 3) array of vertex positions (any float or integer
dtype; converted once to float64), F an (m, 3) integer array of vertex indices
(counter-clockwise seen from outside). Arrays are used as given; read_mesh()
applies the CLI's input hygiene to files.

Conventions (METHOD.md):
- "forward" is first mesh -> second mesh: samples on the FIRST mesh (the
  original), exact point-to-triangle distances to the second.
- Distances are in the meshes' own length unit; "relative" values divide by the
  bounding-box diagonal of the FIRST mesh ("metro" ones by Metro's widened
  union box).
- H > 0 where the surface is convex with outward normals (unit sphere: +1);
  roughness is computed on the mesh scaled to mean vertex distance 1 from the
  centroid, so sigma and D_L are dimensionless.
- threads=None or 0 uses all cores (or OMP_NUM_THREADS), as the CLI's --threads 0;
  results do not depend on the thread count. The GIL is released while
  computing.

Errors: ValueError for bad arrays, options or unusable meshes (the message
names the argument), FileNotFoundError / OSError for files that are missing or
unreadable, RuntimeError for numerical failures.)doc";

//! read_mesh().
constexpr const char* kReadMeshDoc = R"doc(Reads a .ply, .obj, .off or .stl file with the input hygiene of the CLI:
unreferenced vertices dropped, polygons fan-triangulated, faces with a repeated
corner dropped; coordinates as double precision.

Returns V (n, 3) float64 and F (m, 3) int32. With report=True also a dict:
path, file_vertices, file_faces, unreferenced_vertices_removed,
polygons_triangulated, repeated_index_faces_removed (the names of the JSON
"mesh" object) and vertex_scalars (PLY vertex properties other than x, y, z,
name -> (n,) float64 array, e.g. exact_H from `meshdiff generate`).

Raises FileNotFoundError if the file does not exist, OSError if it cannot be
read or parsed, ValueError if it is not a usable mesh (no faces, NaN/Inf
coordinates, index out of range).)doc";

//! The keyword options of compare() and compare_files(), appended to both docstrings.
constexpr const char* kCompareOptionsDoc = R"doc(
Options (keyword-only, named like the CLI flags of `meshdiff compare`; None:
not given, the library's default, as a flag left out). The rules and limits
are the library's, the CLI's too (docs/cli.md states the limits; LIMITS holds
them): a bad value is a ValueError, a wrong type a TypeError, naming the keyword.
  levels=None           ring levels L (ints >= 1, or "1-5,10"); None: 1..20  [--levels]
  radii=None            metric levels: radii > 0 on the unit-scaled mesh, or "default";
                        adds d_r per radius (METHOD.md 5a)                 [--radii]
  global_level=True     also the global level                              [--no-global]
  curvature=None        H estimator: jet (default), goldfeather (the paper's),
                        quadric, meyer                                     [--curvature]
  weighting=None        row weighting of the goldfeather and quadric fits: none
                        (default), inverse-square; refused with jet        [--weighting]
  measure=None          sigma (default) or corsini (METHOD.md 6a)          [--measure]
  unbiased_variance=False  corsini: variance with divisor n - 1            [--unbiased-variance]
  normalize=None        scaling before curvature: paper (default), area (sqrt(area/4pi), does
                        not drift under decimation), original (both in the original's frame)  [--normalize]
  trim=None             trimmed sigma: the share (0..0.25) of vertices with the largest |D|
                        left out at every level; None: 0, the paper's      [--trim]
  bootstrap=None        resamples of the vertices for a 95% bootstrap interval of sigma
                        at every level ("sigma_interval"; 0..10000; None: none) [--bootstrap]
  bootstrap_seed=None   seed of the resamples (None: 1)                    [--bootstrap-seed]
  paper=False           the paper's exact method: goldfeather fit without row weights,
                        paper normalisation, untrimmed sigma; a curvature, weighting,
                        normalize or trim that contradicts it is a ValueError  [--paper]
  local=True            the local roughness difference: per level, the RMS over the processed
                        mesh's vertices of the detail on its L-rings of the change of H (the
                        original's H at the closest point); per radius the same on the original's
                        balls; in ["roughness_distance"]["local"] (levels, rms, radii, rms_radii,
                        global)  [--no-local]
  local_trim=None       the share of the vertices with the largest |difference| left out of
                        each local RMS (0..0.25); None: 0.05              [--local-trim]
  k=None                the constant of d_L = ln(|s'-s|/s + k) - ln(k); 1e-4  [-k]
  roughness=True        compute both profiles and d_L                      [--no-roughness]
  distance=True         compute the surface distance                       [--no-distance]
  samples=None          samples per direction (None: 10 x the larger face count, as Metro)  [-n]
  density=None          samples per unit area instead of a count           [--density]
  face_sampling=None    similar (Metro's lattice, default) or montecarlo   [--face-sampling]
  seed=None             seed of montecarlo sampling (default 1)            [--seed]
  vertex_samples=True, edge_samples=True, face_samples=True   sample kinds [--no-*-samples]
  hausdorff=None        certified (default): an interval [lower, upper] holding each one-sided
                        Hausdorff distance, with where it is attained; sampled: the sampled
                        maxima only                                        [--hausdorff]
  hausdorff_tolerance=None  width of that interval relative to the value; 1e-4 unless only
                        the absolute one is given                          [--hausdorff-tolerance]
  hausdorff_abs_tolerance=None  the width in the meshes' unit; with both, the interval stops
                        at max(relative x value, absolute), as math.isclose [--hausdorff-abs-tolerance]
  hausdorff_budget=None most triangle bounds per direction                 [--hausdorff-budget]
  fscore=None           F-score thresholds relative to the original's diagonal,
                        e.g. [0.001, 0.005] -> surface_distance["fscore"]  [--fscore]
  histogram=None        bins of each direction's histogram, 0 or None: none [--histogram]
  json=None             also write the JSON report to this path            [--json]
  distance_map=None, distance_map_original=None, distance_maps=None
                        write distance maps (PLY), as the CLI              [--distance-map, ...]
  samples_out=None      write both directions' samples (PLY point cloud)   [--samples-out]
  html=None             write the HTML report (one self-contained page)    [--html]
  color_range=None      (MIN, MAX), 'LO:HI', 'max' or 'pNN' (percentile)   [--color-range]
                        of the distance colours (default p99, maps and html)
  html_face_budget=None most faces the HTML report draws per mesh (>= 1000;
                        default 250000); above it a mesh is drawn clustered,
                        the numbers stay the full mesh's; needs html    [--html-face-budget]
  threads=None          OpenMP threads; None or 0: all cores               [--threads]
Python only (no CLI flag):
  maps=False            also result["maps"], per-vertex float64 arrays kept by the comparison
                        itself (the numbers of --distance-maps and --vertex-data, for every
                        normalize): distance_original (n1,), distance_processed (n2,) in the
                        meshes' unit, signed_distance_* where the other mesh can be signed
                        against; D_original (n1, L+G), D_processed (n2, L+G): D_L per vertex on
                        the normalised mesh, a column per level and the global one last (NaN:
                        undefined); D_radii_* (n, R) with radii; local_processed (n2, levels of
                        roughness_distance["local"]) with the distance half. No report number moves.
  index_original=None, index_processed=None
                        a meshdiff.DistanceIndex of that mesh, built once and reused (e.g. one
                        original against many processed meshes) instead of one built per call;
                        the same numbers, bit for bit. It must be of that very mesh (vertex and
                        face counts, coordinates, faces), else a ValueError naming the keyword.
)doc";

//! compare() (followed by kCompareOptionsDoc).
constexpr const char* kCompareDoc = R"doc(Compares the original mesh (V1, F1) with the processed mesh (V2, F2): both
roughness profiles, the per-level roughness distance d_L and the Metro-style
surface distance. Returns the dict of `meshdiff ORIGINAL PROCESSED --json`
(schema "meshdiff.compare/2"): keys schema, meshdiff_version, original,
processed (each a "meshdiff.profile/1" dict), roughness_distance,
surface_distance (None for a half switched off; with the area-weighted means,
chamfer, fscore and psnr of METHOD.md section 6), same_connectivity (None with
same_connectivity_unavailable when the meshes' connectivity differs). Surface distances are in the
meshes' unit; "forward" samples the original (V1, F1); "relative" values divide
by the original's bounding-box diagonal. The arrays' "path" is "<array V1>" and
"<array V2>"; arrays get no input hygiene (isolated vertices are reported as
warnings). F1 or F2 None (or an empty (0, 3) array) makes that side a point
cloud: its points are its samples (point-to-surface or point-to-point
distances; "distance_kind" per direction), roughness is skipped
(roughness_unavailable says why); see METHOD.md section 6.

Example: meshdiff.compare(V, F, V2, F2, levels=[1, 5, 20])["surface_distance"]["hausdorff"]["upper"]
)doc";

//! compare_files() (followed by kCompareOptionsDoc).
constexpr const char* kCompareFilesDoc =
    R"doc(As compare() on two files read as read_mesh() reads them (a file with
vertices and no faces is a point cloud, as in `meshdiff compare`): the same dict as
`meshdiff ORIGINAL PROCESSED --json` with the same options, bit for bit (the
"path" fields are the paths as given here).

Raises FileNotFoundError / OSError for missing or unreadable files.
)doc";

//! The keyword options of profile() and profile_file(), appended to both docstrings.
constexpr const char* kProfileOptionsDoc = R"doc(
Options (keyword-only, as `meshdiff profile`; None: the library's default):
  levels=None, radii=None, global_level=True, curvature=None, weighting=None,
  measure=None, unbiased_variance=False, normalize=None (paper or area), trim=None,
  bootstrap=None, bootstrap_seed=None, paper=False,
  threads=None   (see compare());
  with radii (or "default": 0.0125 * 2**(k/2), k = 0..8) the dict also holds
  "radii", "sigma_radii" and "radius_details" (METHOD.md 5a); with
  measure="corsini" it is the dict of `meshdiff profile --measure corsini`.
  json=None          also write the JSON report to this path          [--json]
  vertex_data=None   write the normalised mesh with H, D_L per vertex [--vertex-data]
  html=None          write the HTML report (one self-contained page)  [--html]
  color_range=None   R of the symmetric H colour range of vertex_data [--color-range]
  exact=False        also the profile of the exact H stored in the input
                     (under "exact"), and the error of the estimate   [--exact]
  exact_property=None  the vertex property holding it ("exact_H")     [--exact-property]
  html_face_budget=None  most faces the HTML report draws (>= 1000;
                     default 250000); needs html                      [--html-face-budget]
)doc";

//! profile() (followed by kProfileOptionsDoc).
constexpr const char* kProfileDoc = R"doc(The roughness profile of one mesh: the dict of `meshdiff profile MESH --json`
(schema "meshdiff.profile/1"): sigma per level and globally (dimensionless: the
mesh is scaled to mean vertex distance 1 from its centroid first), the
normalisation, curvature statistics, per-level details (vertices used, share of
sigma^2 of the worst 0.1% of vertices, their ids) and warnings.
)doc";

//! profile_file() (followed by kProfileOptionsDoc).
constexpr const char* kProfileFileDoc = R"doc(profile() of a file read as read_mesh() reads it: bit for bit the dict of
`meshdiff profile PATH --json`.
)doc";

//! corsini_profile().
constexpr const char* kCorsiniProfileDoc =
    R"doc(Corsini et al.'s dihedral-angle roughness of one mesh (METHOD.md 6a): the dict
of `meshdiff profile MESH --measure corsini --json` (schema "meshdiff.corsini/1").
In it, "corsini" holds per level L the area-weighted mean over the vertices of
the variance of the dihedral angles of the edges within L rings (rad^2), the
global variance, and the multi-scale roughness (the mean over the levels).
levels: ring levels (each >= 1); global_level: add the global level;
unbiased: variance with divisor n - 1 instead of n.
)doc";

//! mean_curvature().
constexpr const char* kMeanCurvatureDoc =
    R"doc(Per-vertex mean curvature H, an (n,) float64 array in 1 / (the mesh's length
unit), NaN where undefined (isolated vertices; boundary vertices for "meyer").
Sign: H > 0 where convex with outward normals (a sphere of radius r: +1/r).
method: "jet" (cubic jet, the default), "goldfeather" (the paper's cubic
fit), "quadric" or "meyer" (cotangent formula). Not normalised: profile() and roughness() estimate H on
the mesh scaled to mean vertex distance 1, i.e. H_there = H * scale.
)doc";

//! roughness().
constexpr const char* kRoughnessDoc =
    R"doc(Per-vertex roughness: D[i, j] = D_L(i) = H(i) - mean of H over the vertices
within L = levels[j] edges of i (i excluded), on the mesh scaled to mean vertex
distance 1 from its centroid (dimensionless; normalize="area": to sqrt(area /
4 pi) about its area-weighted centroid, as profile()). D is (n, len(levels)) float64,
with one more column, the global level (mean over all other vertices), when
global_level=True; NaN where D is undefined (undefined H, or no neighbour with
a defined H). sigma[j] = sqrt(mean of D[:, j]^2 over the non-NaN entries),
the profile's sigma_L (same order).
)doc";

//! surface_distance().
constexpr const char* kSurfaceDistanceDoc =
    R"doc(Metro-style surface distance between the first mesh A = (V1, F1) and the second
B = (V2, F2), in the meshes' length unit. Returns the "surface_distance" object
of compare(): forward (A -> B: samples on A, distance to B's surface) and
backward (B -> A) statistics min, max, mean, rms, std, p50, p95, p99, p999, sample
counts, and "relative" (divided by A's bounding-box diagonal); hausdorff (max
of both maxima), diagonal, metro_diagonal, sampling.

With return_samples=True, forward and backward also hold the samples behind the
statistics: points (k, 3) float64, distances (k,) float64 (exact distance to
the other surface), kinds (k,) uint8 (0 vertex, 1 edge, 2 face: see
SAMPLE_KINDS), elements (k,) int64 (the vertex, a face of the edge, or the
face sampled) and signed_distances (k,) float64 (positive outside the other
surface; None when "signed" is None). The statistics are the same bit for bit.

hausdorff="certified" certifies both one-sided Hausdorff distances as compare()
does (its default there): "hausdorff" then holds an interval [lower, upper] and
where it is attained; hausdorff_tolerance, hausdorff_abs_tolerance and
hausdorff_budget are compare()'s. None (the default here) or "sampled": the
sampled maxima only, as before.

Example: meshdiff.surface_distance(V1, F1, V2, F2, hausdorff="certified")["hausdorff"]["upper"]
)doc";

//! vertex_distances().
constexpr const char* kVertexDistancesDoc =
    R"doc(The exact distance of every vertex of the first mesh (V1; isolated vertices
included) to the surface of the second (V2, F2), an (n1,) float64 array in the
meshes' unit: a per-vertex distance map of the first mesh. F1 is validated
only.
)doc";

//! The class DistanceIndex.
constexpr const char* kDistanceIndexDoc =
    R"doc(A bounding-volume hierarchy over the triangles of (V, F), built once and queried
many times for exact closest points (point-to-triangle; no distance cut-off).
The index keeps its own copy of the mesh. Queries are thread-safe and release
the GIL. compare(..., index_original=index) (or index_processed=) reuses it
instead of building one of that mesh per comparison.
)doc";

//! DistanceIndex.query().
constexpr const char* kQueryDoc = R"doc(For each row of P ((k, 3), any float dtype): distance (k,) float64 to the
closest point of the surface, face (k,) int64 (the face it lies on; the lowest
index on ties), closest_point (k, 3) float64. As libigl's
point_mesh_squared_distance, but with distances, not squared distances.
)doc";

//! The docstrings of DistanceIndex's read-only properties.
constexpr const char* kNFacesDoc = "number of indexed triangles";
constexpr const char* kBoundsDoc = "(min, max): the box of the indexed triangles";
constexpr const char* kMemoryBytesDoc = "approximate heap memory of the index";

}  // namespace meshdiff::python
