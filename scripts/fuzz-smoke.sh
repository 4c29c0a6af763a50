#!/bin/sh
# Fuzz smoke test of the readers (not part of ctest): configures a separate clang
# build with MEDIALAXIS_BUILD_FUZZERS=ON, builds the libFuzzer targets, runs each
# for FUZZ_SECONDS (default 30) from a small seed corpus, and prints the number of
# executions and whether a crash was found. Exit status 1 when one was.
#   scripts/fuzz-smoke.sh            build dir: build-fuzz/ next to the sources
#   FUZZ_SECONDS=300 FUZZ_BUILD_DIR=/tmp/fz scripts/fuzz-smoke.sh
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-30}
fuzzers="FuzzMedialMeshReader FuzzMedialOFFReader FuzzMedialBallPLYReader"

# Static libraries: the instrumented reader code is linked into each fuzzer.
mkdir -p "$build"
cmake -S "$root" -B "$build" -G Ninja \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMEDIALAXIS_BUILD_FUZZERS=ON -DBUILD_SHARED_LIBS=OFF -DBUILD_TESTING=OFF \
  -DMEDIALAXIS_WRAP_PYTHON=OFF -DPython3_EXECUTABLE=/usr/bin/python3 >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log"; exit 2; }
ninja -C "$build" -j2 $fuzzers

# Seeds: one valid file of each kind and a few variants; the dictionary holds the keywords.
seeds="$build/fuzz-seeds"
mkdir -p "$seeds/FuzzMedialMeshReader" "$seeds/FuzzMedialOFFReader" "$seeds/FuzzMedialBallPLYReader" \
  "$build/fuzz-artifacts"
printf '3 3 1\nv 0 0 0 1\nv 1 0 0 0.5 7\nv 0 1 0 0.25\ne 0 1\ne 1 2\ne 2 0\nf 0 1 2\n' \
  >"$seeds/FuzzMedialMeshReader/triangle.ma"
printf '# comment\n2 1 0\n\nv -1.5e-3 +2 3 0\nv 1 1 1 1e300\ne 1 0\n' >"$seeds/FuzzMedialMeshReader/edge.ma"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 2 3 255 0 0\n' >"$seeds/FuzzMedialOFFReader/quad.off"
printf 'COFF 3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n' >"$seeds/FuzzMedialOFFReader/coff.off"
printf 'NOFF\n# normals\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n' >"$seeds/FuzzMedialOFFReader/noff.off"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty double radius\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1\n1 0 0 0.5\n0 1 0 0.25\n0 1\n3 0 1 2\n' \
  >"$seeds/FuzzMedialBallPLYReader/ascii.ply"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty uchar x\nproperty short y\nproperty uint z\nproperty float r\nend_header\n\001\002\000\003\000\000\000\000\000\200\077' \
  >"$seeds/FuzzMedialBallPLYReader/binary.ply"
printf 'kw1="ply"\nkw2="format binary_big_endian 1.0"\nkw3="element vertex "\nkw4="property list uchar int vertex_indices"\nkw5="property double radius"\nkw6="end_header"\nkw7="element edge "\nkw8="property int vertex1"\n' \
  >"$build/fuzz-ply.dict"
printf 'kw1="v"\nkw2="e"\nkw3="f"\nkw4="nan"\nkw5="inf"\nkw6="1e308"\nkw7="# "\nkw8="\\x0d\\x0a"\n' \
  >"$build/fuzz-ma.dict"
printf 'kw1="OFF"\nkw2="COFF"\nkw3="NOFF"\nkw4="CNOFF"\nkw5="4OFF"\nkw6="BINARY"\nkw7="nan"\nkw8="# "\n' \
  >"$build/fuzz-off.dict"

status=0
for fuzzer in $fuzzers; do
  case $fuzzer in
    FuzzMedialMeshReader) dict=fuzz-ma.dict ;;
    FuzzMedialBallPLYReader) dict=fuzz-ply.dict ;;
    *) dict=fuzz-off.dict ;;
  esac
  corpus="$build/fuzz-corpus/$fuzzer"
  mkdir -p "$corpus"
  log="$build/$fuzzer.log"
  set +e
  "$build/bin/$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="$build/$dict" -artifact_prefix="$build/fuzz-artifacts/$fuzzer-" \
    "$corpus" "$seeds/$fuzzer" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  if [ $rc -eq 0 ]; then
    echo "$fuzzer: ${runs:-?} executions in ${seconds} s, no crash"
  else
    status=1
    echo "$fuzzer: ${runs:-?} executions, CRASH (exit $rc); log $log, inputs in $build/fuzz-artifacts/"
    grep -m 5 -E 'ERROR|SUMMARY|invariant' "$log" || true
  fi
done
exit $status
