#!/usr/bin/env bash
# The installed package from a separate project: `cmake --install` into an empty prefix, then
# examples/cpp configured with only that prefix (find_package(pagor) + pagor::core, pagor::eval), built and
# run on the generated scene. Usage: consumer_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CXX_COMPILER
set -euo pipefail
build=$1 source=$2 work=$3 cxx=$4
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in include/pagor/pagor.hpp include/pagor/registration.hpp include/pagor/eval/eval.hpp \
         lib/cmake/pagor/pagorConfig.cmake \
         lib/cmake/pagor/pagorConfigVersion.cmake lib/cmake/pagor/pagorTargets.cmake; do
  [ -f "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
# The registration API is narrow: the harness is its own header set, internals are not installed.
for f in include/pagor/util/voxel_grid.hpp include/pagor/sets include/pagor/io/file_lock.hpp; do
  [ ! -e "$prefix/$f" ] || { echo "FAIL: $f is installed (an internal)"; exit 1; }
done
if grep -n "#include.*pagor/eval/" "$prefix/include/pagor/pagor.hpp"; then
  echo "FAIL: pagor.hpp includes the evaluation harness"; exit 1
fi
# Nothing of this build in the package files (the example's build below shows that the public
# headers need none of core/src).
if grep -n "$source\|$build" "$prefix"/lib/cmake/pagor/*.cmake; then
  echo "FAIL: the package config names the source or build tree"; exit 1
fi

cmake -S "$source/examples/cpp" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
out=$("$work/build/register_clouds")
echo "$out"
echo "$out" | grep -q "^accepted: " || { echo "FAIL: the example did not accept the generated scene"; exit 1; }
echo PASS
