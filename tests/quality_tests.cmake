# Quality area: the measured accuracy of the sharpener (issue 4).
#   quality.fast_subset         the generated shapes, resampled by the real meshlabserver
#                               ("Uniform Mesh Resampling", 1%) and by the project's own
#                               marching cubes, sharpened by both methods, measured with
#                               mesh-distance: never worse than the input, sphere and exact
#                               shapes unchanged, the paper method's reduction factors.
#   quality.hausdorff_crosscheck  mesh-distance agrees with MeshLab's "Hausdorff Distance".
#   quality.hausdorff_meshlab_mode  mesh-distance --sampling meshlab agrees with MeshLab's
#                               "Hausdorff Distance" (vertices, edges, faces) within 5% (issue 19).
#   quality.families_subset     the benchmark's new sampler families on generated shapes (issue
#                               19): OpenVDB remesh and TSDF scans closed 2-manifolds, accepted by
#                               the sharpener, reduction factors and worse counts against floors,
#                               MeshLab's UnSharp Mask peer measured (skipped without OpenVDB or
#                               Open3D).
#   quality.fandisk_targets     fandisk (../shared/meshes) resampled by MeshLab at 2/1/0.5%:
#                               the met headline targets: extended at 1%, and auto below the
#                               paper's 0.43% at 1% (skipped without ../shared).
#   quality.cad_as_is           the ../shared meshes sharpened as they are (auto, extended):
#                               no vertex thrown far away (skipped without ../shared).
#   quality.thin_wall           test_meshes/real/tube.off (a wall 1.3 cells thick) by OpenVDB and
#                               MeshLab's CSG at 1%: the default method makes neither worse
#                               (skipped without OpenVDB).
#   quality.on_plane            lblock_tilted and plate_holes by MeshLab's Isotropic Explicit
#                               Remeshing: exactly sampled features with a few far samples are
#                               sharpened, none made worse.
#   quality.long_move           octa-flower17k (../shared) by MeshLab's Screened Poisson: a
#                               petal tip's long moves from samples off their planes stay at
#                               rest, the input not made worse (skipped without ../shared).
#   quality.saddle_corners      cross_prism by MeshLab's Uniform Mesh Resampling at 1% and
#                               0.5%: the flat top folded at each saddle corner is tiled again,
#                               the max error down at least x3, none made worse.
#   quality.mostly_on_planes    bevelled_block and lblock_tilted by the project's marching
#                               cubes at 1%: features with a few samples off their planes, or
#                               partly refused, are sharpened; factors against floors.
#   quality.smooth_planes       cross_prism by MeshLab's Screened Poisson: the default method
#                               sharpens a smooth part made of planes; rocker-arm (../shared, a
#                               freeform part) by OpenVDB at 1% not made worse (checked when
#                               ../shared and OpenVDB are there).
#   quality.bend_with_feature   cylinder_block and lblock_tilted by OpenVDB at 2%: vertices whose
#                               flank bends away near a corner move with their feature; factors
#                               against floors, none made worse (skipped without OpenVDB).
#   quality.region_planes       cylinder_block and lblock_tilted by Screened Poisson at depth 7:
#                               new vertices on their planar regions' own planes, edges
#                               stopped at corners; factors against floors, none made worse.
#   quality.rough_planes        cross_prism and lblock_tilted scanned (TSDF, noise 0): a rough
#                               input's planar faces flattened onto their planes, its features
#                               left; RMS factors against floors, none made worse (skipped
#                               without Open3D).
#   quality.raised_features     a slab with bosses and ribs 1-3 scan voxels high (authored by
#                               the checker), scanned (TSDF, noise 0 and 0.2 voxel): its
#                               planar faces flattened, the raised features kept (their
#                               reference samples no farther), whole RMS against a floor
#                               (skipped without Open3D).
#   quality.exact_sampling      bevelled_block by OpenVDB as Blender's voxel remesh with
#                               Preserve Volume at 1% and 0.5%: on a mesh sampled exactly its
#                               designed bevels are kept; RMS factors against floors, none made
#                               worse (skipped without OpenVDB).
#   quality.partly_sharp        cross_prism by OpenVDB as Blender's voxel remesh with Preserve
#                               Volume at 1% and 0.5%: sharp already at its convex edges,
#                               chamfered at its concave ones, which are sharpened up to the
#                               saddle corners; RMS factors against floors, none made worse
#                               (skipped without OpenVDB).
#   quality.corner_cells        cylinder_block and lblock_tilted by OpenVDB at 1% and 0.5%: the
#                               remesher's vertex in a convex corner's cell goes onto a face's
#                               plane; max factors against floors, none made worse (skipped
#                               without OpenVDB).
#   quality.coincident_corners  the cube by OpenVDB at 2% and 1%: faces left without area by
#                               new vertices sharing one target no longer keep the remesher's
#                               middle row off both faces; max factors against floors, none
#                               made worse (skipped without OpenVDB).
#   quality.corner_patch        pyramid, octahedron and hexagonal_pyramid by OpenVDB at 1% and
#                               0.5%: a corner of four or more faces whose chamfer holds edges
#                               between faces that touch only there is placed whole at its
#                               planes' point, and a remesher's vertex on an edge goes onto
#                               its planes' line; max factors against floors, none made worse
#                               (skipped without OpenVDB).
#   quality.designed_fillet     plate_holes by OpenVDB as Blender's voxel remesh with Preserve
#                               Volume at 1%: its bottom outline's designed fillet, 2.4 sample
#                               spacings across, is kept; an RMS factor against a floor, not
#                               made worse (skipped without OpenVDB).
#   quality.corner_on_line      pyramid by OpenVDB as Blender's voxel remesh with Preserve Volume
#                               at 1%: samples on the edges into the apex merge into it, the
#                               apex placed whole; a max factor against a floor, not made worse
#                               (skipped without OpenVDB).
# The full benchmark (docs/results.md) is scripts/bench-quality.sh, not a test.
# All exit 77 (skipped) when MeshLab or python3 is not installed, fandisk_targets and
# long_move also without ../shared. Run: ctest -L quality
edge_sharpener_meshlab_script_tests(quality
  fast_subset 900  hausdorff_crosscheck 600  hausdorff_meshlab_mode 600  families_subset 900
  fandisk_targets 900  cad_as_is 600  thin_wall 600  smooth_planes 600  on_plane 600
  long_move 600  saddle_corners 600  mostly_on_planes 600  bend_with_feature 600
  region_planes 600  rough_planes 600  raised_features 600  exact_sampling 600
  partly_sharp 600  corner_cells 600  coincident_corners 600  corner_patch 600
  designed_fillet 600  corner_on_line 600
  ENVIRONMENT "ES_BUILD_DIR=${CMAKE_BINARY_DIR}")
