#!/usr/bin/env python3
"""Holds the studio's result (pagor-studio --headless --json) against the CLI's (pagor register
--json) for the same inputs: the same pose, errors against the ground truth, selection, upper
bound, verdict and diagnosis. Exits non-zero naming every figure that differs."""

import json
import math
import sys


def close(a, b, tol=1e-9):
    """Numbers equal within tol (relative), lists and dicts element by element."""
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return math.isclose(a, b, rel_tol=tol, abs_tol=tol)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(close(x, y, tol) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(close(a[k], b[k], tol) for k in a)
    return a == b


def figures(r):
    """The figures a user reads, by name."""
    out = {
        "T_target_source": r["T_target_source"],
        "selected_level": r["selected_level"],
        "acceptance": r["acceptance"],
        "ground_truth": r["ground_truth"],
        "diagnosis": r["diagnosis"],
        "correspondences.inlier_flags": r.get("correspondences", {}).get("inlier_flags"),
    }
    for i, level in enumerate(r["levels"]):
        for key in ("epsilon", "clique", "score_D", "T_target_source", "translation_error_m",
                    "rotation_error_deg", "success", "precision", "recall", "true_inliers"):
            out["levels[%d].%s" % (i, key)] = level.get(key)
    if out["diagnosis"] is not None:
        out["diagnosis"] = dict(out["diagnosis"])
        out["diagnosis"].pop("time_ms", None)
    return out


def main():
    cli, studio = (json.load(open(p)) for p in sys.argv[1:3])
    a, b = figures(cli), figures(studio)
    wrong = [k for k in a if not close(a[k], b.get(k))]
    for k in wrong:
        print("%s: CLI %s, studio %s" % (k, json.dumps(a[k])[:300], json.dumps(b.get(k))[:300]))
    if cli["config"] != studio["config"]:
        print("the configurations differ")
        wrong.append("config")
    if wrong:
        sys.exit(1)
    print("the studio's figures equal the CLI's (%d compared)" % len(a))


if __name__ == "__main__":
    main()
