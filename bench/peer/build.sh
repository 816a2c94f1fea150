#!/usr/bin/env bash
# Offline build of the KISS-Matcher back end (ROBIN max-core pruning + GNC-TLS solver) and of
# the timing harness `km_backend`. Fetches NOTHING: all sources must already be cloned under
# $PEER_DIR/src/ (a scratch folder outside the repository; default ~/pagor-peer) at these exact
# commits:
#
#   src/KISS-Matcher  MIT-SPARK/KISS-Matcher  09d51175f41ddcafbc94f5bed115473317d963f9
#                     (upstream main, 2025-05-05, "Support Kimera-Multi experiments ..."; the
#                      stored MIT-SPARK snapshot only had the 2024 README-only commit, so this
#                      upstream commit was taken from the fork qza36/KISS-Matcher, whose history
#                      contains it unchanged; cpp/kiss_matcher last touched upstream in 778e930)
#   src/ROBIN         MIT-SPARK/ROBIN         52bab5f2bb6dd68a5febb6bd06bb2ffdff2f75c2 (master, 2025-05-27)
#                     KISS-Matcher's 3rdparty/robin/robin.cmake pins the tag v.1.2.3 (5bcc76e), but
#                     v.1.2.3 no longer compiles against pmc master (it relied on pmc's former
#                     `using namespace std`: "'vector' was not declared" in graph_solvers.cpp).
#                     master differs from v.1.2.3 only by that std:: qualification (#8), a CMake
#                     minimum bump, the README, and xenium pinned to `main` instead of 7ee5ed1.
#   src/pmc           jingnanshi/pmc          a2dfd612a501bca83c47206255dbbff619481f97
#                     (branch master, which ROBIN's cmake/DownloadExternal.cmake pins)
#   src/xenium        mpoeter/xenium          3f08ceac00f54d0992c053de81743b3937aaf543
#                     (branch main, which ROBIN master's cmake/DownloadExternal.cmake pins; header-only)
#
# How it stays offline:
#  * ROBIN's CMake clones pmc and xenium with ExternalProject(GIT_REPOSITORY https://github.com/..).
#    We leave its CMake untouched and redirect those URLs to the local clones with git's
#    `url.<local>.insteadOf` set through GIT_CONFIG_COUNT/KEY/VALUE environment variables.
#  * KISS-Matcher is configured with USE_SYSTEM_EIGEN3/TBB/ROBIN=ON (Debian libeigen3-dev,
#    libtbb-dev, and the ROBIN we just installed into ./install), so none of its FetchContent
#    blocks run; FETCHCONTENT_FULLY_DISCONNECTED=ON as a safety net.
# Debian packages used: cmake g++ libeigen3-dev libtbb-dev libflann-dev liblz4-dev (libgomp).
# Compiler flags: the projects' own Release defaults (ROBIN: CMake Release = -O3 -DNDEBUG;
# KISS-Matcher: "-O3 -Wall" + OpenMP flags, no -DNDEBUG); harness: "-O3 -Wall" like KISS-Matcher;
# no -march=native anywhere (neither project sets it).
# The src/ clones were made with `git clone <local bare mirror> src/<name>` + `git checkout <commit>`
# (ROBIN: master; KISS-Matcher: 09d5117); nothing here touches the network.
set -euo pipefail
HERE=${PEER_DIR:-$HOME/pagor-peer}
HARNESS=$(cd "$(dirname "$0")" && pwd)/harness
SRC=$HERE/src
BUILD=$HERE/build
PREFIX=$HERE/install
JOBS=${JOBS:-2}

check() { # dir expected-commit
  local got; got=$(git -C "$SRC/$1" rev-parse HEAD)
  [[ "$got" == "$2" ]] || { echo "src/$1 is at $got, expected $2" >&2; exit 1; }
}
check KISS-Matcher 09d51175f41ddcafbc94f5bed115473317d963f9
check ROBIN        52bab5f2bb6dd68a5febb6bd06bb2ffdff2f75c2
check pmc          a2dfd612a501bca83c47206255dbbff619481f97
check xenium       3f08ceac00f54d0992c053de81743b3937aaf543

# Redirect ROBIN's github clones to the local copies (no network access happens).
# xenium's git submodules (3rdParty/config, 3rdParty/json, 3rdParty/gtest; `gtest` in older commits) are only for its own tests and
# benchmarks; ExternalProject runs `git submodule update --init --recursive`, so they are marked
# inactive (submodule.<name>.active=false) to keep that step offline and a no-op.
export GIT_CONFIG_COUNT=7
export GIT_CONFIG_KEY_0="url.$SRC/pmc.insteadOf"
export GIT_CONFIG_VALUE_0="https://github.com/jingnanshi/pmc.git"
export GIT_CONFIG_KEY_1="url.$SRC/xenium.insteadOf"
export GIT_CONFIG_VALUE_1="https://github.com/mpoeter/xenium"
export GIT_CONFIG_KEY_2="protocol.file.allow"
export GIT_CONFIG_VALUE_2="always"
export GIT_CONFIG_KEY_3="submodule.3rdParty/config.active"
export GIT_CONFIG_VALUE_3="false"
export GIT_CONFIG_KEY_4="submodule.3rdParty/json.active"
export GIT_CONFIG_VALUE_4="false"
export GIT_CONFIG_KEY_5="submodule.gtest.active"
export GIT_CONFIG_VALUE_5="false"
export GIT_CONFIG_KEY_6="submodule.3rdParty/gtest.active"
export GIT_CONFIG_VALUE_6="false"

mkdir -p "$BUILD" "$PREFIX"

# 1. ROBIN (+ pmc static lib, + xenium headers), Release, tests off.
cmake -S "$SRC/ROBIN" -B "$BUILD/robin" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTS=OFF -DUSE_SYSTEM_EIGEN3=ON \
  -DPMC_BUILD_SHARED=OFF -DCMAKE_INSTALL_PREFIX="$PREFIX"
cmake --build "$BUILD/robin" -j "$JOBS"
cmake --install "$BUILD/robin"

# 2. KISS-Matcher core library (static), Release.
cmake -S "$SRC/KISS-Matcher/cpp/kiss_matcher" -B "$BUILD/kiss_matcher" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release -DUSE_CCACHE=OFF \
  -DUSE_SYSTEM_EIGEN3=ON -DUSE_SYSTEM_TBB=ON -DUSE_SYSTEM_ROBIN=ON \
  -DFETCHCONTENT_FULLY_DISCONNECTED=ON \
  -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_INSTALL_PREFIX="$PREFIX"
cmake --build "$BUILD/kiss_matcher" -j "$JOBS"
cmake --install "$BUILD/kiss_matcher"

# 3. Harness (km_backend) and problem generator (gen_problems).
cmake -S "$HARNESS" -B "$BUILD/harness" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PREFIX"
cmake --build "$BUILD/harness" -j "$JOBS"
ls -l "$BUILD/harness/km_backend" "$BUILD/harness/gen_problems"
