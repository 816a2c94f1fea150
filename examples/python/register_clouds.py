#!/usr/bin/env python3
"""Registers two cloud files with the Python module and prints the selected T_target_source,
the verdict and the pyramid's levels:
register_clouds.py SOURCE TARGET [--source-labels F --target-labels F] [--config FILE.json]"""
import argparse
import json

# README: "Use it as a library" (Python)
import pagor


def register_files(source_path, target_path, source_labels=None, target_labels=None,
                   config=None):
    """Registers two cloud files; config: a dict with the JSON configuration's keys, or None."""
    source, source_labels = pagor.read_cloud(source_path, source_labels)  # .bin, .pcd, .ply
    target, target_labels = pagor.read_cloud(target_path, target_labels)
    result = pagor.register(source, target, source_labels, target_labels, config=config)
    print("T_target_source:\n", result.T_target_source)
    print("accepted:", result.accepted, result.acceptance["reason"])
    for level in result.levels:
        print(f"epsilon {level.epsilon}: clique {level.clique_size}, inliers {level.inliers}")
    return result
# end of snippet


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("--source-labels", help="SemanticKITTI .label file of the source")
    parser.add_argument("--target-labels", help="SemanticKITTI .label file of the target")
    parser.add_argument("--config", help="configuration JSON (the pagor tool's format)")
    args = parser.parse_args()
    config = json.load(open(args.config)) if args.config else None
    result = register_files(args.source, args.target, args.source_labels, args.target_labels,
                            config)
    print("total [ms]:", round(result.timings_ms["total"], 1))


if __name__ == "__main__":
    main()
