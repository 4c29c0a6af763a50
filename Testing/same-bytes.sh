#!/bin/sh
# Runs medial-axis three times with the same seed (1, 2 and 2 threads) and checks that
# the .vtp files are byte-identical, and once more with --stats.   same-bytes.sh MEDIAL_AXIS SCRATCH_DIR
set -eu
cli=$1
dir=$2
mkdir -p "$dir"
"$cli" -n 3000 --seed 42 --threads 1 -o "$dir/run1.vtp"
"$cli" -n 3000 --seed 42 --threads 2 -o "$dir/run2.vtp"
"$cli" -n 3000 --seed 42 --threads 2 -o "$dir/run3.vtp"
cmp "$dir/run1.vtp" "$dir/run2.vtp"
cmp "$dir/run2.vtp" "$dir/run3.vtp"
# --stats measures how far the balls cross the surface as they are solved: same balls.
"$cli" -n 3000 --seed 42 --threads 2 --stats -o "$dir/stats.vtp" > /dev/null
cmp "$dir/run1.vtp" "$dir/stats.vtp"
"$cli" -n 3000 --seed 43 --threads 2 -o "$dir/other-seed.vtp"
if cmp -s "$dir/run1.vtp" "$dir/other-seed.vtp"; then
  echo "a different seed gave the same bytes"
  exit 1
fi
echo "identical: $(wc -c < "$dir/run1.vtp") bytes, 3 runs"
