#!/usr/bin/env bash
# Speed-up of the MPI backend on one machine: the same table (8 paper arenas x 60 and 100 robots x
# 16 seeds = 256 simulations, capped at 6000 ticks) at 1, 4, 8 and 16 ranks of one thread, then
# 4 ranks x 4 threads and one process of 16 threads, and the master's capacity with a null
# objective. Every run must write the same table --json. Prints simulations per second, speed-up
# over 1 rank, and how busy the ranks were; about 4 minutes on 16 cores.
#
#   scripts/mpi_scaling.sh [--ranks "1 4 8 16"] [--seeds 16] [--ticks 6000] [--out DIR] [--build DIR]
#   scripts/mpi_scaling.sh --ranks "1 2 3" --seeds 2 --ticks 3000      # a small check, 2 cores
#
# On a machine without swarmpath's libraries or Open MPI (no apt there), gather everything here and
# carry it:
#   scripts/mpi_scaling.sh --bundle DIR          # here: build, then DIR/ (~30 MB) holds swarmpath,
#                                                # mpi_master, every library they and Open MPI load
#                                                # (the C library and its loader too) and Open MPI
#   scripts/mpi_scaling.sh --use-bundle DIR ...  # there: measure with DIR's programs
set -euo pipefail
cd "$(dirname "$0")/.."

ranks="1 4 8 16"
seeds=16
ticks=6000
out=results/mpi_scaling
build_dir=build/release
bundle=""
make_bundle=""
while (($#)); do
  case $1 in
    --ranks) ranks=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --ticks) ticks=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build_dir=$2; shift 2 ;;
    --bundle) make_bundle=$2; shift 2 ;;
    --use-bundle) bundle=$(cd "$2" && pwd); shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "mpi_scaling: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

# build (release, with the MPI backend) unless it is there
build() {
  if [ -x "$build_dir/swarmpath" ] && [ -x "$build_dir/bench/mpi_master" ] &&
     ldd "$build_dir/swarmpath" | grep -q libmpi; then return; fi
  [ "$build_dir" = build/release ] || { echo "mpi_scaling: no MPI-enabled swarmpath in $build_dir" >&2; exit 2; }
  command -v mpirun >/dev/null || { echo "mpi_scaling: no mpirun: run scripts/install-deps.sh (or use --use-bundle)" >&2; exit 2; }
  cmake --preset release >/dev/null
  cmake --build --preset release -j "$(nproc)" --target swarmpath mpi_master
}

# every shared library an ELF file loads, resolved here
libraries() { ldd "$@" 2>/dev/null | awk '/=> \// {print $3} /^\t\/.*ld-linux/ {print $1}' | sort -u; }

if [ -n "$make_bundle" ]; then
  build
  d=$make_bundle
  rm -rf "$d" && mkdir -p "$d/bin" "$d/lib" "$d/root"
  objcopy --strip-debug "$build_dir/swarmpath" "$d/bin/swarmpath"
  objcopy --strip-debug "$build_dir/bench/mpi_master" "$d/bin/mpi_master"
  # Open MPI's runtime at its own paths under root/ (OPAL_PREFIX moves it there)
  for p in openmpi-bin openmpi-common libopenmpi3 libpmix2; do
    dpkg -L "$p" | while read -r f; do
      case $f in /usr/share/doc/*|/usr/share/man/*|/usr/share/lintian/*) continue ;; esac
      if [ -f "$f" ] && [ ! -L "$f" ]; then mkdir -p "$d/root$(dirname "$f")" && cp "$f" "$d/root$f"; fi
      if [ -L "$f" ]; then mkdir -p "$d/root$(dirname "$f")" && cp -P "$f" "$d/root$f"; fi
    done
  done
  # every library any of them loads, in one folder; programs run through the bundled loader
  elves=$(find "$d/bin" "$d/root" -type f \( -name '*.so*' -o -perm -u+x \) -exec sh -c 'head -c4 "$1" | grep -q ELF && echo "$1"' _ {} \;)
  for l in $(libraries $elves); do cp -L "$l" "$d/lib/"; done
  for l in $(libraries "$d"/lib/*); do cp -Ln "$l" "$d/lib/" 2>/dev/null || true; done
  loader=$(basename "$(libraries "$d/bin/swarmpath" | grep ld-linux)")
  for prog in swarmpath mpi_master; do
    printf '#!/bin/sh\nd=$(dirname "$0")/..\nexec "$d/lib/%s" --library-path "$d/lib" "$d/bin/%s" "$@"\n' "$loader" "$prog" >"$d/bin/$prog-run"
    chmod +x "$d/bin/$prog-run"
  done
  echo "$loader" >"$d/loader"
  bundle=$(cd "$d" && pwd)
  check_bundle=yes
fi

if [ -n "$bundle" ]; then
  # Open MPI, PMIx and hwloc look for their plugins under the bundle, not /usr
  export OPAL_PREFIX=$bundle/root/usr PMIX_PREFIX=$bundle/root/usr/lib/x86_64-linux-gnu/pmix2
  export PMIX_PKGLIBDIR=$PMIX_PREFIX/lib/pmix HWLOC_PLUGINS_PATH=$bundle/no-hwloc-plugins
  loader=$bundle/lib/$(cat "$bundle/loader")
  mpirun=("$loader" --library-path "$bundle/lib" "$bundle/root/usr/bin/orterun")
  swarmpath=$bundle/bin/swarmpath-run
  master=$bundle/bin/mpi_master-run
else
  build
  mpirun=(mpirun)
  swarmpath=$(cd "$build_dir" && pwd)/swarmpath
  master=$(cd "$build_dir" && pwd)/bench/mpi_master
fi
# shared memory between ranks (backed in /tmp: a container's /dev/shm can be tiny), no single-copy
# kernel support needed, no network probing, as root
mpi_args=(--oversubscribe --bind-to none --allow-run-as-root --mca pml ob1 --mca btl self,vader
          --mca btl_vader_single_copy_mechanism none --mca btl_vader_backing_directory /tmp)

# a new bundle proves here that every process it starts loads nothing from this machine's /usr
# (but /bin/sh, which each wrapper runs before it hands over to the bundled loader)
if [ "${check_bundle:-}" = yes ]; then
  trace=$(mktemp -d)
  LD_DEBUG=libs LD_DEBUG_OUTPUT=$trace/ld "${mpirun[@]}" "${mpi_args[@]}" -np 2 "$swarmpath" table \
    --scenarios tests/data/short_chain.toml --robots 8 --seeds 2 --ticks 200 --threads 1 >/dev/null 2>&1 ||
    { echo "mpi_scaling: the bundle does not run here" >&2; exit 1; }
  outside=$(grep -h "calling init" "$trace"/ld.* | awk '{print $NF}' | grep -v "^$bundle/" |
            grep -v -e '/libc\.so\.6$' -e '/ld-linux-x86-64\.so\.2$' | sort -u || true)
  rm -rf "$trace"
  [ -z "$outside" ] || { echo "mpi_scaling: the bundle still loads from this machine: $outside" >&2; exit 1; }
  echo "mpi_scaling: bundle in $bundle ($(du -sh "$bundle" | cut -f1)), checked: its processes load their libraries from it"
  echo "  there: scripts/mpi_scaling.sh --use-bundle DIR (DIR: where it was carried)"
  exit 0
fi

mkdir -p "$out"
: >"$out/summary.md"
say() { echo "$@" | tee -a "$out/summary.md"; }
cores=$(nproc)
table=(table --scenarios configs/scenarios/paper --robots 60,100 --seeds "$seeds" --ticks "$ticks" --mode pf)
tasks=$((8 * 2 * seeds))
say "mpi_scaling: $(uname -n), $cores cores, $(date -u +%FT%TZ); $tasks simulations per run (${table[*]})"
say "| ranks x threads | simulations/s | speed-up | efficiency | busy | same table --json |"
say "|---|---|---|---|---|---|"
base=""
reference=""
measure() {  # measure RANKS THREADS (RANKS 0: one process without mpirun)
  local r=$1 t=$2 name log rate busy same
  name=$([ "$r" = 0 ] && echo "1 process x $t" || echo "$r x $t")
  log=$out/run-$r-$t.err
  if [ "$r" = 0 ]; then
    "$swarmpath" "${table[@]}" --threads "$t" --json "$out/run-$r-$t.json" >/dev/null 2>"$log"
  else
    "${mpirun[@]}" "${mpi_args[@]}" -np "$r" "$swarmpath" "${table[@]}" --threads "$t" \
      --json "$out/run-$r-$t.json" >/dev/null 2>"$log"
  fi || { echo "mpi_scaling: $name failed:" >&2; tail -20 "$log" >&2; exit 1; }
  rate=$(sed -n 's/.*simulations in [0-9.]* s (\([0-9.]*\) per s).*/\1/p' "$log" | tail -1)
  busy=$(sed -n 's/.*busy: \(.*\)$/\1/p; s/.*threads busy \(.*\)$/\1/p' "$log" | tail -1)
  [ -n "$base" ] || base=$rate
  [ -n "$reference" ] || reference=$out/run-$r-$t.json
  same=$(cmp -s "$reference" "$out/run-$r-$t.json" && echo yes || echo NO)
  awk -v n="$name" -v x="$rate" -v b="$base" -v k=$((r > 0 ? r * t : t)) -v busy="$busy" -v s="$same" \
    'BEGIN { printf "| %s | %.2f | %.2f | %.0f %% | %s | %s |\n", n, x, x / b, 100 * x / b / k, busy, s }' |
    tee -a "$out/summary.md"
}
for r in $ranks; do measure "$r" 1; done
if [ "$cores" -ge 16 ]; then
  measure 4 4
  measure 0 16
fi
# the master alone: null tasks to every other rank
top=$(echo "$ranks" | tr ' ' '\n' | sort -n | tail -1)
[ "$top" -ge 2 ] || top=2
"${mpirun[@]}" "${mpi_args[@]}" -np "$top" "$master" 20000 5 1 | tee -a "$out/summary.md"
echo "mpi_scaling: the table in $out/summary.md, each run's log and JSON beside it"
