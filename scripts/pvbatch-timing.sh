#!/bin/sh
# Times medial_pvbatch.py on 1 and 2 MPI ranks against 1 rank with 1 and 2 threads, and a
# tiny run that costs only what every rank repeats (reading and preparation), then checks
# that the 1- and 2-rank balls are the same. Prints the machine load and one JSON line per
# run: rank 0's times from medial_pvbatch.py --timing, the wall time, and the CPU seconds
# of all ranks.
# Usage: sh scripts/pvbatch-timing.sh MESH [SAMPLES]   (after sh scripts/paraview.sh; needs GNU time)
# e.g.   /usr/bin/python3 scripts/big-horse.py ../shared/data/meshes/horse.ply /tmp/horse-loop2.vtp
#        sh scripts/pvbatch-timing.sh /tmp/horse-loop2.vtp 1000000
set -eu
cd "$(dirname "$0")/.."
MESH=$1
SAMPLES=${2:-1000000}
ROOT=$(pwd)/build-paraview/root
export LD_LIBRARY_PATH="$ROOT/usr/lib/x86_64-linux-gnu" OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OUT=$(mktemp -d)
run() { # ranks threads samples output: one JSON line, with the wall time and the CPU
  # seconds of all ranks together (user + system; unlike the wall time, the CPU time
  # hardly depends on what else runs on the machine)
  line=$(/usr/bin/time -f '%e %U %S' -o "$OUT/time" mpiexec -n "$1" --oversubscribe --bind-to none \
    "$ROOT/usr/bin/pvbatch" Examples/ParaView/medial_pvbatch.py "$MESH" "$OUT/$4" --samples "$3" \
    --threads "$2" --timing 2>&1 | grep '^{')
  set -- $(tail -1 "$OUT/time")
  echo "${line%\}}, \"wall\": $1, \"cpu\": $(awk "BEGIN { print $2 + $3 }"), \"load\": \"$(cut -d' ' -f1-3 /proc/loadavg)\"}"
}
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
MESH_SAVED=$MESH; MESH=demo
run 1 1 8 startup.vtp # pvbatch, Python and the plugin: what any run costs
MESH=$MESH_SAVED
run 1 1 1000 prep-1.vtp
run 1 2 1000 prep-2.vtp
run 1 1 "$SAMPLES" r1t1.vtp
run 1 2 "$SAMPLES" r1t2.vtp
run 2 1 "$SAMPLES" r2t1.vtp
"$ROOT/usr/bin/pvpython" ParaView/Testing/same_polydata.py "$OUT/r1t2.vtp" "$OUT/r2t1.vtp" --min-points "$((SAMPLES / 2))" 2>&1 | tail -1
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
rm -rf "$OUT"
