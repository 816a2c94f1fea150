#!/usr/bin/env bash
# The offline pip path, as the README gives it: a venv that sees Debian's packages
# (--system-site-packages: numpy, setuptools), `pip install --no-build-isolation` with no index
# (nothing may be downloaded), then `import pagor` from the venv, outside the source and build
# trees. PAGOR_BUILD_DIR lets setup.py reuse this build tree's module instead of compiling the
# core again. Usage: pip_install_test.sh PYTHON SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
python=$1 source=$2 build=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
"$python" -m venv --system-site-packages "$work/venv"
PAGOR_BUILD_DIR=$build "$work/venv/bin/pip" install --no-build-isolation --no-index \
    --no-cache-dir "$source" > "$work/pip.log" 2>&1 || { cat "$work/pip.log"; echo FAIL; exit 1; }
cd "$work"
"$work/venv/bin/python" - <<'PY'
import pathlib, sys
import numpy  # from Debian, seen through --system-site-packages
import pagor
where = pathlib.Path(pagor.__file__).resolve()
assert where.is_relative_to(pathlib.Path(sys.prefix).resolve()), f"imported {where}, not the venv's"
package = where.parent
for name in ("__init__.py", "results.py", "_inputs.py", "py.typed", "_pagor.pyi"):
    assert (package / name).is_file(), f"{name} is not installed in {package}"
assert not (package / "pybind").exists(), "the C++ sources were installed"
assert pathlib.Path(pagor._pagor.__file__).parent == package
scene = pagor.synthetic_scene(seed=7)
result = pagor.register(scene["source"], scene["target"], scene["source_labels"],
                        scene["target_labels"])
assert result.accepted, result
print(f"pagor {pagor.__version__} from {where}: {result}")
PY
grep -q "^Version: " <<< "$("$work/venv/bin/pip" show pagor)" || { echo "FAIL: no pip metadata"; exit 1; }
echo PASS
