"""The faces of a mesh that lie on a designed feature of its reference, as a face list for the
sharpener's --skip-faces (or --only-faces): the faces whose centroid lies within DISTANCE of
the reference's faces whose normal turns ANGLE degrees (within TOLERANCE) from an axis.
For references whose designed feature is such a family of faces (abc6's 45-degree conical
chamfer: --angle 45), where the generator's own designed-face lists do not reach. With
--within X,Y,Z,R (repeatable), only the reference's faces within R of one of those points
count (octa-flower17k's petal-tip facets: designed.json).

Usage: /usr/bin/python3 bench/study/designed_faces_near.py REF MESH OUT --distance D
       [--angle 45] [--tolerance 5] [--axis z] [--within X,Y,Z,R ...]
"""
import argparse
import sys

import numpy as np

import within


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("reference")
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--distance", type=float, required=True,
                    help="how near a face's centroid must lie (the mesh's units)")
    ap.add_argument("--angle", type=float, default=45.0, help="degrees from the axis")
    ap.add_argument("--tolerance", type=float, default=5.0, help="degrees")
    ap.add_argument("--axis", choices="xyz", default="z")
    within.add_option(ap, "only the reference's faces within R of this point (repeatable)")
    args = ap.parse_args()
    spheres = within.spheres(args, "designed_faces_near")
    try:
        import open3d as o3d
        from scipy.spatial import cKDTree
    except ImportError as e:
        sys.exit(f"designed_faces_near: {e} (Debian python3-open3d, python3-scipy)")
    ref = o3d.io.read_triangle_mesh(args.reference)
    ref.compute_triangle_normals()
    normals = np.asarray(ref.triangle_normals)
    tilt = np.degrees(np.arccos(np.clip(np.abs(normals[:, "xyz".index(args.axis)]), 0, 1)))
    designed = np.abs(tilt - args.angle) <= args.tolerance
    if spheres:
        designed &= within.inside(
            np.asarray(ref.vertices)[np.asarray(ref.triangles)].mean(axis=1), spheres)
    if not designed.any():
        sys.exit("designed_faces_near: no reference face turns that far from the axis")
    # Points on the designed faces, spaced well under --distance.
    v, t = np.asarray(ref.vertices), np.asarray(ref.triangles)[designed]
    points = []
    for a, b, c in v[t]:
        n = int(np.ceil(max(np.linalg.norm(b - a), np.linalg.norm(c - a)) / (args.distance / 4)))
        for i in range(n + 1):
            for j in range(n + 1 - i):
                points.append(a + (b - a) * i / n + (c - a) * j / n)
    mesh = o3d.io.read_triangle_mesh(args.mesh)
    centroids = np.asarray(mesh.vertices)[np.asarray(mesh.triangles)].mean(axis=1)
    near, _ = cKDTree(np.array(points)).query(centroids)
    faces = np.flatnonzero(near <= args.distance)
    with open(args.out, "w") as f:
        f.write(f"# faces within {args.distance:g} of the reference's faces turned "
                f"{args.angle:g} +- {args.tolerance:g} degrees from {args.axis}"
                + "".join(f", within {w}" for w in args.within) + "\n")
        f.write("\n".join(map(str, faces)) + "\n")
    print(f"{len(faces)} of {len(centroids)} faces written to {args.out}")


if __name__ == "__main__":
    main()
