#!/usr/bin/python3
"""tsdf-scan IN OUT.ply --voxel-fraction F --noise K [--views 26] [--resolution 320] [--seed S]

A depth-camera scan of a mesh, one of the quality benchmark's sampler families (issue 19):
depth images rendered from VIEWS directions around the shape (the 26 directions of a 3x3x3
grid's outer cells), Gaussian depth noise of K voxels added (seeded: the same call gives the
same mesh), fused by Open3D's ScalableTSDFVolume (voxel = F x the diagonal, truncation 4
voxels) and extracted by its marching cubes. The largest connected component is kept and its
duplicated vertices merged; whether the result is closed and manifold is printed (JSON), not
repaired: a mesh the sharpener refuses is a finding of the benchmark.

The depth renderer is our own (Debian's Open3D 0.16 RaycastingScene.cast_rays returns no hits):
a z-buffer rasterizer in numpy, perspective-correct depth, pixel centres sampled.
Run with Debian's /usr/bin/python3 (python3-open3d, python3-numpy).
"""
import argparse
import json
import math
import sys

import numpy as np

try:
    import open3d as o3d
except ImportError:  # the caller reports "Open3D not installed" and skips the family
    sys.stderr.write("tsdf-scan: Open3D (Debian python3-open3d) is not installed\n")
    sys.exit(3)

DISTANCE = 1.6  # camera to the shape's centre, in diagonals: the whole shape is in view
HALF_FOV_TAN = 0.36  # > tan(asin(0.5 / DISTANCE)): a half-diagonal sphere fits in the image
TRUNCATION_VOXELS = 4.0
PAIRS_PER_CHUNK = 1_000_000  # (triangle, pixel) candidates per rasterization step (memory)


def view_directions(count):
    dirs = [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)
            if (x, y, z) != (0, 0, 0)]
    dirs = np.array(dirs, dtype=float)
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    if count > len(dirs):
        raise SystemExit(f"tsdf-scan: at most {len(dirs)} views")
    return dirs[:count]


def camera_extrinsic(direction):
    """World -> camera (x right, y down, z forward) for a camera at DISTANCE * direction
    looking at the origin."""
    centre = DISTANCE * direction
    forward = -direction
    up = np.array([0.0, 0.0, 1.0]) if abs(forward[2]) < 0.9 else np.array([0.0, 1.0, 0.0])
    right = np.cross(forward, -up)
    right /= np.linalg.norm(right)
    down = np.cross(forward, right)
    rot = np.stack([right, down, forward])
    ext = np.eye(4)
    ext[:3, :3] = rot
    ext[:3, 3] = -rot @ centre
    return ext


def render_depth(vertices, triangles, extrinsic, focal, size):
    """Z-depth image (0 = no surface) of the triangles seen through a pinhole camera."""
    cam = vertices @ extrinsic[:3, :3].T + extrinsic[:3, 3]
    z = cam[:, 2]
    u = focal * cam[:, 0] / z + size / 2.0
    v = focal * cam[:, 1] / z + size / 2.0
    tu, tv, tz = u[triangles], v[triangles], z[triangles]
    # Pixel (i, j) has its centre at (i + 0.5, j + 0.5).
    i0 = np.clip(np.ceil(tu.min(1) - 0.5), 0, size).astype(np.int64)
    i1 = np.clip(np.floor(tu.max(1) - 0.5), -1, size - 1).astype(np.int64)
    j0 = np.clip(np.ceil(tv.min(1) - 0.5), 0, size).astype(np.int64)
    j1 = np.clip(np.floor(tv.max(1) - 0.5), -1, size - 1).astype(np.int64)
    width = np.maximum(i1 - i0 + 1, 0)
    height = np.maximum(j1 - j0 + 1, 0)
    counts = width * height
    area = ((tu[:, 1] - tu[:, 0]) * (tv[:, 2] - tv[:, 0])
            - (tu[:, 2] - tu[:, 0]) * (tv[:, 1] - tv[:, 0]))
    keep = (counts > 0) & (np.abs(area) > 1e-12) & (tz.min(1) > 0)
    ids = np.nonzero(keep)[0]
    best = np.full(size * size, np.inf)
    start = 0
    while start < len(ids):
        # a chunk of triangles with at most PAIRS_PER_CHUNK candidate pixels (at least one)
        cum = np.cumsum(counts[ids[start:]])
        stop = start + max(1, int(np.searchsorted(cum, PAIRS_PER_CHUNK)))
        t = ids[start:stop]
        start = stop
        n = counts[t]
        tri = np.repeat(t, n)
        offset = np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)
        w = width[tri]
        pi = i0[tri] + offset % w
        pj = j0[tri] + offset // w
        px = pi + 0.5
        py = pj + 0.5
        a = area[tri]
        # barycentric coordinates by edge functions
        b0 = ((tu[tri, 1] - px) * (tv[tri, 2] - py) - (tu[tri, 2] - px) * (tv[tri, 1] - py)) / a
        b1 = ((tu[tri, 2] - px) * (tv[tri, 0] - py) - (tu[tri, 0] - px) * (tv[tri, 2] - py)) / a
        b2 = 1.0 - b0 - b1
        inside = (b0 >= 0) & (b1 >= 0) & (b2 >= 0)
        if not inside.any():
            continue
        tri, pi, pj = tri[inside], pi[inside], pj[inside]
        b0, b1, b2 = b0[inside], b1[inside], b2[inside]
        inv_z = b0 / tz[tri, 0] + b1 / tz[tri, 1] + b2 / tz[tri, 2]
        depth = 1.0 / inv_z
        np.minimum.at(best, pj * size + pi, depth)
    best[~np.isfinite(best)] = 0.0
    return best.reshape(size, size)


def largest_component(mesh):
    clusters, counts, _ = mesh.cluster_connected_triangles()
    clusters = np.asarray(clusters)
    if len(counts) > 1:
        mesh.remove_triangles_by_mask(clusters != int(np.argmax(counts)))
        mesh.remove_unreferenced_vertices()
    return len(counts)


def edge_counts(triangles):
    """(boundary edges, edges with more than two faces). Open3D's is_watertight also tests
    self-intersection, which is slow and not what the sharpener requires."""
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
                                    triangles[:, [2, 0]]]), axis=1)
    _, uses = np.unique(edges, axis=0, return_counts=True)
    return int((uses == 1).sum()), int((uses > 2).sum())


def write_binary_ply(path, vertices, triangles):
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {len(triangles)}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        f.write(np.asarray(vertices, dtype="<f4").tobytes())
        faces = np.zeros(len(triangles), dtype=[("n", "u1"), ("v", "<i4", 3)])
        faces["n"] = 3
        faces["v"] = triangles
        f.write(faces.tobytes())


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--voxel-fraction", type=float, default=0.01)
    ap.add_argument("--noise", type=float, default=0.0, help="depth noise sigma, in voxels")
    ap.add_argument("--views", type=int, default=26)
    ap.add_argument("--resolution", type=int, default=256, help="image width = height, pixels")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    mesh = o3d.io.read_triangle_mesh(args.input)
    vertices = np.asarray(mesh.vertices, dtype=float)
    triangles = np.asarray(mesh.triangles, dtype=np.int64)
    if len(triangles) == 0:
        raise SystemExit(f"tsdf-scan: {args.input}: no triangles")
    lo, hi = vertices.min(0), vertices.max(0)
    centre = 0.5 * (lo + hi)
    diag = float(np.linalg.norm(hi - lo))
    unit = (vertices - centre) / diag  # the scan works at diagonal 1 (Open3D's float TSDF)

    voxel = args.voxel_fraction
    size = args.resolution
    focal = (size / 2.0) / HALF_FOV_TAN
    intrinsic = o3d.camera.PinholeCameraIntrinsic(size, size, focal, focal, size / 2.0 - 0.5,
                                                  size / 2.0 - 0.5)
    volume = o3d.pipelines.integration.ScalableTSDFVolume(
        voxel_length=voxel, sdf_trunc=TRUNCATION_VOXELS * voxel,
        color_type=o3d.pipelines.integration.TSDFVolumeColorType.NoColor)
    rng = np.random.default_rng(args.seed)
    blank = o3d.geometry.Image(np.zeros((size, size, 3), dtype=np.uint8))
    for direction in view_directions(args.views):
        extrinsic = camera_extrinsic(direction)
        depth = render_depth(unit, triangles, extrinsic, focal, size)
        noise = rng.normal(0.0, args.noise * voxel, depth.shape) if args.noise > 0 else 0.0
        depth = np.where(depth > 0, depth + noise, 0.0).astype(np.float32)
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(
            blank, o3d.geometry.Image(depth), depth_scale=1.0, depth_trunc=4.0 * DISTANCE,
            convert_rgb_to_intensity=False)
        volume.integrate(rgbd, intrinsic, extrinsic)

    scan = volume.extract_triangle_mesh()
    scan.remove_duplicated_vertices()
    scan.remove_degenerate_triangles()
    scan.remove_unreferenced_vertices()
    components = largest_component(scan)
    out_v = np.asarray(scan.vertices) * diag + centre
    out_t = np.asarray(scan.triangles)
    if len(out_t) == 0:
        raise SystemExit("tsdf-scan: the TSDF produced no surface")
    # outward faces: positive enclosed volume
    a, b, c = (out_v[out_t[:, k]] for k in range(3))
    if np.einsum("ij,ij->i", a, np.cross(b, c)).sum() < 0:
        out_t = out_t[:, ::-1]
    write_binary_ply(args.output, out_v, out_t)
    boundary, non_manifold = edge_counts(out_t)
    print(json.dumps({"vertices": len(out_v), "faces": len(out_t), "components": components,
                      "boundary_edges": boundary, "non_manifold_edges": non_manifold,
                      "closed_manifold": boundary == 0 and non_manifold == 0
                      and bool(scan.is_vertex_manifold()),
                      "voxel": voxel * diag, "noise_voxels": args.noise, "views": args.views}))


if __name__ == "__main__":
    main()
