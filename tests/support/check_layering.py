#!/usr/bin/env python3
"""Checks that the sources include only what their layer may see.

The core's folders are layers in the order of the pipeline (util and the stages' parameters of
params.hpp, io, front, graph, pose, verify, indoor, eval); the top-level config gathers those
parameters into one document, the pipeline runs them and the
report writes their result. A file may include its own layer and the layers below it, never above:
a stage does not know the configuration document, the pipeline or the sets that run it. The
studio's folders are layers too (render, widgets, runners, state, scene, panels, then the studio).
Usage: check_layering.py REPO_ROOT; prints each violation and exits 1 when there is one.
"""
import os
import re
import sys

# (path prefix, level): the longest matching prefix gives a file's level.
LAYERS = [
    ("core/include/pagor/types.hpp", 0), ("core/include/pagor/errors.hpp", 0),
    ("core/include/pagor/util/", 1), ("core/src/util/", 1),
    ("core/include/pagor/io/", 2), ("core/src/io/", 2),
    ("core/include/pagor/front/", 3), ("core/src/front/", 3),
    ("core/include/pagor/graph/", 4), ("core/src/graph/", 4),
    ("core/include/pagor/pose/", 5), ("core/src/pose/", 5),
    ("core/include/pagor/verify/", 6), ("core/src/verify/", 6),
    ("core/include/pagor/indoor/", 7), ("core/src/indoor/", 7),
    ("core/include/pagor/config.hpp", 8), ("core/src/config", 8),
    ("core/include/pagor/pipeline.hpp", 9), ("core/src/pipeline.cpp", 9),
    # The diagnosis judges a whole pipeline run against the ground truth.
    ("core/include/pagor/verify/diagnosis.hpp", 10), ("core/src/verify/diagnosis.cpp", 10),
    ("core/include/pagor/report.hpp", 11), ("core/src/report.cpp", 11),
    ("core/include/pagor/registration.hpp", 11), ("core/src/registration.cpp", 11),
    # pagor::eval: the harness and the generators, on top of the core.
    ("core/include/pagor/eval/", 12), ("core/src/eval/", 12),
    ("core/include/pagor/pagor.hpp", 13),
    # Every stage's parameters sit with util: the tables' vocabulary, nothing of a stage.
    ("core/include/pagor/params.hpp", 1),
    # the studio
    ("app/studio/render/", 20),
    ("app/studio/widgets/", 21),
    ("app/studio/runners/", 22),
    ("app/studio/state/", 23),
    ("app/studio/scene/", 24),
    ("app/studio/panels/", 25),
    ("app/studio/studio.", 26), ("app/studio/main.cpp", 27),
]
INCLUDE_ROOTS = {
    "core": ["core/include", "core/src"],
    "app/studio": ["app/studio", "app", "core/include", "core/src"],
}


def level_of(path):
    best = None
    for prefix, level in LAYERS:
        if path.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, level)
    return best[1] if best else None


def resolve(root, path, included):
    here = os.path.dirname(path)
    for base in [here] + next(v for k, v in INCLUDE_ROOTS.items() if path.startswith(k)):
        candidate = os.path.normpath(os.path.join(base, included))
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def main(root):
    violations = []
    checked = 0
    for top in INCLUDE_ROOTS:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith((".hpp", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root)
                level = level_of(path)
                if level is None:
                    continue
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    for n, line in enumerate(f, 1):
                        m = re.match(r'\s*#\s*include\s*"([^"]+)"', line)
                        if not m:
                            continue
                        target = resolve(root, path, m.group(1))
                        if target is None:
                            continue
                        checked += 1
                        target_level = level_of(target)
                        if target_level is not None and target_level > level:
                            violations.append(f"{path}:{n}: includes {target}, a layer above it")
    for v in violations:
        print(v)
    print(f"{checked} includes checked, {len(violations)} against the layers")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
