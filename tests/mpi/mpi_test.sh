#!/usr/bin/env bash
# The MPI backend against one process: the same command under mpirun (3 ranks, oversubscribed)
# and in one process must write byte-identical files, a run killed mid-generation must resume to
# the files of an uninterrupted run (with or without MPI), and a scenario that cannot be read must
# fail the job on rank 0 with the file named.
#   mpi_test.sh CASE SWARMPATH SOURCE_DIR MPIEXEC SCRATCH
# CASE: evolve | nsga2 | table | evaluate | resume | bad-scenario | srun-copies. MPIEXEC "" = built
# without MPI (every case but srun-copies is then skipped).
set -uo pipefail
case_name=$1 B=$2 S=$3 MPIEXEC=$4 W=$5/$1

# srun -n 4 without an MPI plugin: each copy refuses to run the whole command (with or without MPI)
if [ "$case_name" = srun-copies ]; then
  mkdir -p "$5"
  SLURM_STEP_NUM_TASKS=4 SLURM_PROCID=2 "$B" table --seeds 1 >/dev/null 2>"$5/srun-copies.err"
  rc=$?
  cat "$5/srun-copies.err"
  [ $rc -eq 2 ] && grep -q "srun started 4 tasks (this is task 2)" "$5/srun-copies.err" || { echo "FAIL: exit $rc"; exit 1; }
  echo "PASS: srun-copies"
  exit 0
fi

if [ -z "$MPIEXEC" ]; then
  echo "skipped: this build has no MPI backend (configure with -DSWARMPATH_MPI=ON and Open MPI installed:"
  echo "         apt install libopenmpi-dev openmpi-bin, as scripts/install-deps.sh does)"
  exit 77
fi
rm -rf "$W" && mkdir -p "$W" && cd "$W" || exit 1
# ranks on one machine share memory; containers often forbid the kernel's cross-memory attach that
# Open MPI would use for large messages, and the copy through shared memory works everywhere
export OMPI_MCA_btl_vader_single_copy_mechanism=none
mpi() { timeout 300 "$MPIEXEC" --oversubscribe --allow-run-as-root -np "$@"; }
fail() { echo "FAIL: $*"; exit 1; }
same() {  # same DIR_A DIR_B FILE...
  local a=$1 b=$2; shift 2
  for f in "$@"; do
    [ -s "$a/$f" ] || fail "$a/$f is missing or empty"
    cmp -s "$a/$f" "$b/$f" || { diff "$a/$f" "$b/$f" | head -20; fail "$a/$f and $b/$f differ"; }
  done
  echo "  same: $* ($a, $b)"
}

# a tiny evolve config: short_chain at 8 robots, 3000 ticks, 2 seeds, population 4
cat >tiny.toml <<TOML
name = "tiny"
params = "$S/genomes/default.toml"
mode = "pf"
seed = 7
[tune]
w_away = {}
p_turn = { lo = 0.002, hi = 0.2, log = true }
T_explore0 = { lo = 200, hi = 2000, step = 50 }
[evaluation]
scenarios = ["$S/tests/data/short_chain.toml"]
robots = [8]
seeds = 2
max_ticks = 3000
[optimizer]
name = "cmaes"
population = 4
[budget]
generations = 4
[reevaluate]
top_k = 2
seeds = 2
TOML
evolve_files="log.csv best.toml checkpoint.json fitness.svg"

case $case_name in
evolve)
  "$B" evolve --config tiny.toml --out one --threads 2 --no-wall-time >/dev/null 2>one.err || { cat one.err; fail "one process"; }
  mpi 3 "$B" evolve --config tiny.toml --out mpi1 --threads 1 --no-wall-time >/dev/null 2>mpi1.err || { cat mpi1.err; fail "mpirun -np 3"; }
  mpi 3 "$B" evolve --config tiny.toml --out mpi2 --threads 2 --no-wall-time >/dev/null 2>mpi2.err || { cat mpi2.err; fail "mpirun -np 3, 2 threads"; }
  grep -q "3 MPI ranks x 1 thread" mpi1.err || { cat mpi1.err; fail "the MPI run did not use 3 ranks"; }
  grep -q "busy: rank 0" mpi1.err || { cat mpi1.err; fail "no MPI summary"; }
  same one mpi1 $evolve_files
  same one mpi2 $evolve_files
  ;;
nsga2)
  sed -e 's/"cmaes"/"nsga2"/' -e 's/population = 4/population = 8/' -e '/top_k/d' -e 's/generations = 4/generations = 3/' tiny.toml >nsga2.toml
  printf '[objectives]\nuse = ["path", "ticks", "robots"]\nmin_success = 0.5\nreference = [2.0, 3000, 1.0]\n' >>nsga2.toml
  "$B" evolve --config nsga2.toml --out one --threads 2 --no-wall-time >/dev/null 2>one.err || { cat one.err; fail "one process"; }
  mpi 3 "$B" evolve --config nsga2.toml --out mpi --threads 1 --no-wall-time >/dev/null 2>mpi.err || { cat mpi.err; fail "mpirun -np 3"; }
  same one mpi log.csv checkpoint.json pareto.csv hypervolume.svg pareto.svg
  [ "$(ls one/front)" = "$(ls mpi/front)" ] || fail "front/ holds other files"
  for f in one/front/*.toml; do same one mpi "front/$(basename "$f")" >/dev/null; done
  echo "  same: front/*.toml ($(ls one/front | wc -l) points)"
  ;;
table)
  args=(--scenarios "$S/configs/scenarios/paper/env1.toml" "$S/configs/scenarios/paper/env4.toml" --robots 20,30
        --seeds 2 --ticks 2500 --mode both)
  "$B" table "${args[@]}" --threads 2 --json one.json --csv one.csv --md one.md >/dev/null 2>one.err || { cat one.err; fail "one process"; }
  mpi 3 "$B" table "${args[@]}" --threads 1 --json mpi.json --csv mpi.csv --md mpi.md >/dev/null 2>mpi.err || { cat mpi.err; fail "mpirun -np 3"; }
  same . . one.json >/dev/null
  cmp -s one.json mpi.json || fail "table --json differs"
  cmp -s one.csv mpi.csv || fail "table --csv differs"
  cmp -s one.md mpi.md || fail "table --md differs"
  echo "  same: table --json, --csv, --md"
  ;;
evaluate)
  args=(--params "$S/genomes/default.toml" --against "$S/genomes/paper-single.toml" --scenarios "$S/configs/scenarios/paper/env3.toml"
        --robots 20 --seeds 3 --ticks 2500 --mode ta)
  "$B" evaluate "${args[@]}" --threads 2 --json one.json >one.md 2>one.err || { cat one.err; fail "one process"; }
  mpi 3 "$B" evaluate "${args[@]}" --threads 1 --json mpi.json >mpi.md 2>mpi.err || { cat mpi.err; fail "mpirun -np 3"; }
  cmp -s one.json mpi.json || fail "evaluate --json differs"
  cmp -s one.md mpi.md || fail "evaluate's table differs"
  echo "  same: evaluate --json and its table"
  ;;
resume)
  "$B" evolve --config tiny.toml --out one --threads 2 --no-wall-time >/dev/null 2>one.err || { cat one.err; fail "one process"; }
  # a worker dies as generation 2 (batch 3) begins: the job ends, generations 0 and 1 are kept
  SWARMPATH_MPI_FAULT=1:3 mpi 3 "$B" evolve --config tiny.toml --out killed --threads 1 --no-wall-time >/dev/null 2>killed.err
  rc=$?
  [ $rc -ne 0 ] || { cat killed.err; fail "the job went on after a rank died"; }
  grep -q '"generation": 2,' killed/checkpoint.json || { head -8 killed/checkpoint.json; fail "the checkpoint is not generation 2's"; }
  [ ! -e killed/best.toml ] || fail "best.toml written by a killed run"
  echo "  a dead worker ended the job (mpirun exit $rc); checkpoint after generation 2 intact"
  cp -r killed killed-then-mpi
  "$B" evolve --config tiny.toml --out killed --threads 2 --no-wall-time --resume >/dev/null 2>resume.err || { cat resume.err; fail "resume without MPI"; }
  same one killed $evolve_files
  mpi 3 "$B" evolve --config tiny.toml --out killed-then-mpi --threads 1 --no-wall-time --resume >/dev/null 2>resume-mpi.err || { cat resume-mpi.err; fail "resume under MPI"; }
  same one killed-then-mpi $evolve_files
  # a checkpoint written by one process, continued under MPI
  "$B" evolve --config tiny.toml --out plain --threads 2 --no-wall-time --generations 2 >/dev/null 2>plain.err || { cat plain.err; fail "two generations in one process"; }
  mpi 3 "$B" evolve --config tiny.toml --out plain --threads 1 --no-wall-time --resume >/dev/null 2>plain-mpi.err || { cat plain-mpi.err; fail "resume under MPI"; }
  same one plain $evolve_files
  # rank 0 itself killed (a scheduler's kill), then resumed under MPI
  SWARMPATH_MPI_FAULT=0:4 mpi 3 "$B" evolve --config tiny.toml --out rank0 --threads 1 --no-wall-time >/dev/null 2>rank0.err
  rc=$?
  [ $rc -ne 0 ] || fail "the job went on after rank 0 died"
  grep -q '"generation": 3,' rank0/checkpoint.json || { head -8 rank0/checkpoint.json; fail "the checkpoint is not generation 3's"; }
  mpi 3 "$B" evolve --config tiny.toml --out rank0 --threads 1 --no-wall-time --resume >/dev/null 2>rank0-resume.err || { cat rank0-resume.err; fail "resume after rank 0 died"; }
  same one rank0 $evolve_files
  ;;
bad-scenario)
  sed "s|$S/tests/data/short_chain.toml|$W/no/such/arena.toml|" tiny.toml >bad.toml
  mpi 3 "$B" evolve --config bad.toml --out bad --threads 1 >/dev/null 2>bad.err
  rc=$?
  cat bad.err
  [ $rc -eq 2 ] || fail "exit code $rc, not 2"
  grep -q "$W/no/such/arena.toml" bad.err || fail "the file is not named"
  [ "$(grep -c "no/such/arena.toml" bad.err)" -le 2 ] || fail "named by more than rank 0"
  echo "  exit 2 on rank 0, the file named"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo "PASS: $case_name"
