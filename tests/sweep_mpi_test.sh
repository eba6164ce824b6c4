#!/usr/bin/env bash
# acst_sweep under mpirun: a two-case sweep on 2 ranks gives the table of the same sweep run in
# turn in one process, row for row, every column but wall time, threads and "resumed"; the log says
# that both ranks worked. Usage: sweep_mpi_test.sh ACST_SWEEP MPIEXEC SWEEP.json WORK_DIR
set -euo pipefail
tool=$1 mpiexec=$2 sweep=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
"$tool" --quiet --no-plot --threads 1 --output "$work/in_turn" "$sweep"
"$mpiexec" -n 2 "$tool" --no-plot --output "$work/ranks" "$sweep" 2>"$work/ranks.log"
grep -q "2 to run on 2 workers" "$work/ranks.log" || { echo "FAIL: the log does not say 2 workers:"; cat "$work/ranks.log"; exit 1; }

# The table without the columns that may differ between runs (found by name in the header).
strip() {
  awk -F, '/^#/ { next }
           !header { for (i = 1; i <= NF; i++) drop[i] = ($i == "wall_s" || $i == "threads" || $i == "resumed"); header = 1 }
           { line = ""; for (i = 1; i <= NF; i++) if (!drop[i]) line = line $i ","; print line }' "$1"
}
strip "$work/in_turn/table.csv" >"$work/in_turn.rows"
strip "$work/ranks/table.csv" >"$work/ranks.rows"
if ! diff "$work/in_turn.rows" "$work/ranks.rows"; then
  echo "FAIL: the tables differ"
  exit 1
fi
rows=$(grep -c ',done,' "$work/ranks.rows" || true)
[ "$rows" -eq 2 ] || { echo "FAIL: expected 2 cases done, found $rows"; cat "$work/ranks.rows"; exit 1; }

# Under a budget too small for any case the ranks start none and exit 75; run again without it,
# they run both to the same table.
set +e
"$mpiexec" -n 2 "$tool" --no-plot --budget 0.0001 --output "$work/budget" "$sweep" >"$work/budget.out" 2>&1
rc=$?
set -e
[ "$rc" -eq 75 ] || { echo "FAIL: a budget too small for any case gave exit $rc, not 75"; cat "$work/budget.out"; exit 1; }
grep -q "too small for any case" "$work/budget.out" || { echo "FAIL: no 'too small for any case'"; cat "$work/budget.out"; exit 1; }
"$mpiexec" -n 2 "$tool" --quiet --no-plot --output "$work/budget" "$sweep" >/dev/null 2>&1
strip "$work/budget/table.csv" >"$work/budget.rows"
diff "$work/in_turn.rows" "$work/budget.rows" || { echo "FAIL: the table after the budget differs"; exit 1; }
echo "PASS: 2 cases on 2 ranks, the same table as in turn, also after a budget too small for any case"
