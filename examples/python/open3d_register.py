#!/usr/bin/env python3
"""Registers two Open3D point clouds with pagor and draws them aligned:
open3d_register.py SOURCE TARGET [--config FILE.json] [--save aligned.ply] [--no-window].

The clouds are read with pagor.read_cloud, which also gives their semantic labels (KITTI .bin +
.label, PCD or PLY with a label field), and become open3d.geometry.PointCloud objects, which
pagor.register takes as they are (it reads their points in place, no copy on the Python side).
The source is drawn in orange after the transform, the target in blue."""
import argparse
import json

import numpy as np
import open3d as o3d

import pagor


def open3d_cloud(path, labels_path=None):
    points, labels = pagor.read_cloud(path, labels_path)
    return o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points.astype(np.float64))), labels


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("--source-labels")
    parser.add_argument("--target-labels")
    parser.add_argument("--config", help="configuration JSON (the pagor tool's format)")
    parser.add_argument("--save", help="write both clouds, aligned and coloured, to this file")
    parser.add_argument("--no-window", action="store_true", help="do not open a window")
    args = parser.parse_args()
    config = json.load(open(args.config)) if args.config else None

    source, source_labels = open3d_cloud(args.source, args.source_labels)
    target, target_labels = open3d_cloud(args.target, args.target_labels)
    result = pagor.register(source, target, source_labels, target_labels, config=config)
    if result.T_target_source is None:
        raise SystemExit("no level gave a valid pose")
    print(result)
    print("T_target_source:")
    for row in result.T_target_source:
        print(" ".join(f"{v:12.6f}" for v in row))

    source.transform(result.T_target_source)
    source.paint_uniform_color([1.0, 0.6, 0.0])
    target.paint_uniform_color([0.0, 0.6, 0.9])
    if args.save:
        o3d.io.write_point_cloud(args.save, source + target)
        print("wrote", args.save)
    if not args.no_window:
        o3d.visualization.draw_geometries([source, target], window_name="pagor: aligned clouds")


if __name__ == "__main__":
    main()
