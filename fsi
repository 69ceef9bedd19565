#!/usr/bin/env bash
# fsi: the one entry point. Installs missing Debian packages, configures and builds with
# CMake (Release), then runs a case, validates it, runs the tests or the benchmarks.
#
#   ./fsi run [-o DIR] [-v] [--resolution coarse|medium|fine] [--end-time S] [--restart] CASE_DIR
#                             build, then run the case (results in CASE_DIR/output/): the
#                             structure solver alone, or the coupler and its participants
#                             (after the fluid's precursor run, if the case has one)
#   ./fsi run --participant coupler|structure|fluid CASE_DIR
#                             start only that process (several machines; see docs/cluster.md)
#   ./fsi submit [--partition P] [--time T] [--fluid-nodes N] [--dry-run] CASE_DIR [CASE_DIR ...]
#                             run on a SLURM cluster: a coupled case as a heterogeneous job, several
#                             cases as a job array; requeued jobs resume from their checkpoints
#                             (docs/cluster.md)
#   ./fsi check CASE_DIR      validate a case without running it
#   ./fsi fuzz [--seconds N] [envelope|coupler_channel|case_file ...]  fuzz the message decoder,
#                             the coupler's message handling and the case parser with libFuzzer
#                             (clang; N s each, default 300; crashers in build-fuzz/crashes/)
#   ./fsi keys [--force] CASE_DIR  make the CURVE keys of a case with coupling.security: curve
#                             (coupling.keys_dir; kept when present; docs/security.md)
#   ./fsi test                build and run all tests (plus a short fuzzing run and a sanitizer pass of the structure tests)
#   ./fsi test --stability    the stability suite alone (thresholds in build/stability/stability.md)
#   ./fsi test --cluster      the SLURM tests alone (a two-node SLURM started on this machine)
#   ./fsi bench [structure|transport|coupling|fluid|pump|pump_rag|mpi_coupling]  run a benchmark (fluid, pump: vs stock pimpleFoam;
#                             mpi_coupling: the Lagrangian side of a step on 1 and 2 MPI ranks against the points;
#                             also mesh_surface, kernel_stencil, body_indicator: one module's kernels)
#   ./fsi report [--quick] [--skip-speed] [--skip-stability] [--only-speed]  speed-against-error
#                             report (report/REPORT.md, error_vs_cost.png; about 30 min, 8 with
#                             --quick), with a speed section (the benches against their references);
#                             --only-speed: that section alone (report/SPEED.md)
#   ./fsi schema              print the case-file reference (Markdown; docs/case-reference.md)
#   ./fsi build               install and build everything (what ./fsi test does first)
#   ./fsi pump-design FILE [--write DIR]  check a pump design file; the duty and volute its design
#                             rules give; --write: generate the geometry (DIR/impeller.stl, casing.stl,
#                             geometry.yaml, geometry.png; docs/pump-design.md)
#   ./fsi pump-curve [--points 0.36,0.6,0.8,1.0,1.2] [--method ibm|ami|both] [--jobs N]
#                    [--resolution NAME] [--end-time S] [-o DIR] CASE_DIR
#                             a pump case at several flow rates (fractions of its design flow), the
#                             impeller penalized, body-fitted (AMI) or both: pump_curve.csv and .png
#   ./fsi pump-compare [--flow-fraction 1.0] [--revolutions 8] [--ranks 2] [--from DIR] [-o DIR] CASE_DIR
#                             the penalized impeller against the body-fitted (AMI) one on the same mesh
#                             from one settled state: head, torque by part, leak, cost (comparison.md)
#   ./fsi coupling-study [--only laws|implicit]  the coupling laws at equal cost and implicit coupling
#                             against explicit on real runs (study/coupling/COUPLING.md; docs/coupling.md)
#   ./fsi ercoftac-study [--levels coarse,medium] [--revolutions 10] [--jobs 2] [-o DIR]
#                             the ERCOFTAC pump (cases/ercoftac-pump) penalized and body-fitted at each
#                             mesh level against its measurement (study/ercoftac-pump/ERCOFTAC.md)
#   ./fsi disc-study [--only laminar|turbulent] [--levels 2] [--jobs 2] [-o DIR]
#                             the rotating disc (cases/rotating-disc) penalized and body-fitted on the
#                             same meshes against the analytic and Daily & Nece torques (study/rotating-disc/DISC.md)
#   ./fsi rag-ensemble [--runs 8] [--seed 1] [--flow-fraction 1.0] [--sizes LxW,...] [--jobs N]
#                      [--resolution NAME] [--end-time S] [-o DIR] CASE_DIR
#                             rag releases into a pump case (cases/rag-in-pump): P(hang-up) with its
#                             interval, residence and wrap distributions (ensemble.csv, ensemble.png)
#   ./fsi feed-compare [--designs A.yaml,B.yaml] [--flow-fractions 1,0.36] [--seeds 4] [--rags N] [--jobs N]
#                      [--submit] [-o DIR] CASE_DIR
#                             the same rag feed (cases/rag-feed) into two pump designs over seeds: rags to
#                             clog per design with intervals, P(A outlasts B) (compare.md, compare.png);
#                             --submit: as a SLURM job array, then again without it to compare
#
# The cases: cases/README.md. Their results: docs/results.md.
#
# Environment: FSI_BUILD_DIR (default build), FSI_JOBS (default: number of cores),
# FSI_SANITIZE=0 skips the sanitizer pass of './fsi test', FSI_FUZZ_SECONDS=0 its fuzzing (default 20 s a target).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD=${FSI_BUILD_DIR:-$ROOT/build}
# The Python half is one package (python/fsi/): on PYTHONPATH once, for everything started from here
# (runs, the cases' own scripts, CTest, studies); `python3 -m fsi.<module>` runs a module.
export PYTHONPATH="$ROOT/python${PYTHONPATH:+:$PYTHONPATH}"
# ... and the executables' folder, where the package finds its geometry engine (fsi-surface-query).
export FSI_BIN_DIR=${FSI_BIN_DIR:-$BUILD/bin}
JOBS=${FSI_JOBS:-$(nproc)}
PACKAGES=(cmake ninja-build g++ ccache git pkg-config libeigen3-dev libspdlog-dev libfmt-dev libhdf5-dev
          libyaml-cpp-dev libcli11-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libnanoflann-dev
          libgtest-dev libgmock-dev libbenchmark-dev python3-h5py python3-matplotlib python3-numpy
          paraview python3-paraview python3-yaml openmpi-bin libzmq3-dev cppzmq-dev libprotobuf-dev protobuf-compiler
          libgmsh-dev python3-gmsh python3-scipy ffmpeg iproute2 nftables clang-14 libclang-rt-14-dev
          slurm-wlm munge)

say() { printf 'fsi: %s\n' "$*" >&2; }
die() { printf 'fsi: error: %s\n' "$*" >&2; exit 2; }

ensure_packages() {
  local missing=()
  for p in "${PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  say "installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq >/dev/null
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# build DIR [cmake args...] [-- targets...]: configure once, then build quietly (log in DIR/build.log).
build() {
  local dir=$1; shift
  local args=() targets=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do args+=("$1"); shift; done
  [ $# -gt 0 ] && shift && targets=("$@")
  # One build at a time per build folder: two ./fsi commands started together (two runs in two
  # terminals) would otherwise race on the same objects and libraries and link broken executables.
  mkdir -p "$dir"
  local lock_fd
  exec {lock_fd}>"$dir/.build.lock"
  if ! flock -n "$lock_fd"; then
    say "waiting for another ./fsi building in $dir"
    flock "$lock_fd"
  fi
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S "$ROOT" -B "$dir" -G Ninja "${args[@]}" >"$dir/configure.log" 2>&1 ||
      { cat "$dir/configure.log" >&2; die "CMake configuration failed (log: $dir/configure.log)"; }
  fi
  # Quiet when there is nothing to do. (A dry run cannot tell: the globbed case list makes
  # ninja re-check the configuration on every call.) Say something once the build has run
  # for two seconds, i.e. when there is real work.
  local target_args=()
  [ ${#targets[@]} -gt 0 ] && target_args=(--target "${targets[@]}")
  cmake --build "$dir" -j "$JOBS" "${target_args[@]}" >"$dir/build.log" 2>&1 &
  local pid=$! ticks=0
  while kill -0 "$pid" 2>/dev/null && [ "$ticks" -lt 20 ]; do sleep 0.1; ticks=$((ticks + 1)); done
  if kill -0 "$pid" 2>/dev/null; then say "building in $dir (log: $dir/build.log)"; fi
  if ! wait "$pid"; then
    grep -E "error|Error" -A3 "$dir/build.log" | head -60 >&2
    die "build failed (full log: $dir/build.log)"
  fi
  exec {lock_fd}>&-
}

# OpenFOAM v1912: Debian's package + the headers of the same version from its source package,
# cached in build-deps/ (scripts/ensure_openfoam.sh; quiet when done).
ensure_openfoam() { "$ROOT/scripts/ensure_openfoam.sh" || die "OpenFOAM provisioning failed (see above)"; }

# prepare [TARGET...]: packages, OpenFOAM, then a build of the given targets (default: everything,
# tests and benchmarks included). A run needs only the four process executables, and the pump
# generator (a case's prepare.py may generate its geometry: cases/centrifugal-pump).
RUN_TARGETS=(fsi-structure fsi-coupler fsi-prescribed-flow fsi-openfoam-fluid fsi-pump-design fsi-surface-query)
prepare() {
  ensure_packages
  ensure_openfoam
  build "$BUILD" -DCMAKE_BUILD_TYPE=Release -DFSI_REQUIRE_OPENFOAM=ON -- "$@" # no target: all
}

# The launcher (python/fsi/fsi_launch.py) asks fsi-coupler --plan which processes the case needs
# and starts them; the picture is drawn where the structure ran.
cmd_run() {
  [ $# -ge 1 ] || die "usage: ./fsi run [-o DIR] [-v] [--resolution NAME] [--end-time S] [--restart] [--participant NAME] CASE_DIR"
  prepare "${RUN_TARGETS[@]}"
  local launch=(/usr/bin/python3 -m fsi.fsi_launch --bin-dir "$BUILD/bin")
  local status=0 out="" participant="" prev=""
  for a in "$@"; do
    case "$prev" in --participant) participant=$a ;; esac
    case "$a" in --participant=*) participant=${a#--participant=} ;; esac
    prev=$a
  done
  "${launch[@]}" "$@" || status=$?
  [ "$status" -le 1 ] || return "$status"
  [ -z "$participant" ] || [ "$participant" = structure ] || return "$status"
  out=$("${launch[@]}" --print-output-dir "$@" 2>/dev/null) || return "$status"
  local results="$out/structure.h5"
  if [ -n "$out" ] && [ -f "$results" ]; then
    if /usr/bin/python3 -m fsi.plot_structure "$results" "$out/summary.png" 2>/dev/null; then
      say "picture: $out/summary.png"
    fi
    # Probes (structure.h5 /probes) and forces (coupling.h5) against time: python/fsi/plot_quantities.py.
    if /usr/bin/python3 -m fsi.plot_quantities "$out" 2>/dev/null && [ -f "$out/quantities.png" ]; then
      local tables=""
      [ -f "$out/probes.csv" ] && tables="$out/probes.csv"
      [ -f "$out/forces.csv" ] && tables="${tables:+$tables, }$out/forces.csv"
      say "quantities: $out/quantities.png${tables:+ ($tables)}"
    fi
    # OpenFOAM runs: |U| on a slice through the sheet at a few times (python/fsi/plot_flow.py).
    if [ -d "$out/openfoam" ] && /usr/bin/python3 -m fsi.plot_flow "$out" >/dev/null 2>&1; then
      say "flow pictures: $(ls "$out"/flow_t*.png | tr '\n' ' ')"
    fi
  fi
  # A case's own quantities (its README names them): cases/<case>/postprocess.py OUT CASE_DIR,
  # after the structure's pictures (it may redraw them), or after the flow alone (a pump's operating point).
  local case_dir  # the launcher's reading of the arguments: the case folder may come before the options
  case_dir=$("${launch[@]}" --print-case-dir "$@" 2>/dev/null) || case_dir=${!#}
  if [ -n "$out" ] && { [ -f "$results" ] || [ -f "$out/forces.csv" ]; } && [ -f "$case_dir/postprocess.py" ]; then
    local made
    # python/ on PYTHONPATH (above): a copy of the case away from the repository imports the package too
    if made=$(/usr/bin/python3 "$case_dir/postprocess.py" "$out" "$case_dir" 2>&1); then
      if [ "$status" -eq 0 ]; then
        say "case quantities: $made (in $out)"
      else  # what a failed run got to: say so, its numbers are not the case's
        say "case quantities of the failed run, up to where it stopped: $made (in $out)"
      fi
    else
      say "warning: $case_dir/postprocess.py failed: $(echo "$made" | tail -1)"
    fi
  fi
  return "$status"
}

cmd_check() {
  [ $# -ge 1 ] || die "usage: ./fsi check CASE_DIR"
  prepare fsi-structure fsi-pump-design
  # A case's generated inputs first (cases/<case>/prepare.py: the pump's geometry), as ./fsi run.
  local case_dir=${!#}
  if [ -f "$case_dir/prepare.py" ]; then
    /usr/bin/python3 "$case_dir/prepare.py" "$case_dir" "$BUILD/bin" ||
      die "preparing $case_dir failed (see above)"
  fi
  "$BUILD/bin/fsi-structure" --check "$@"
}

cmd_test() {
  prepare
  if [ "${1:-}" = "--stability" ]; then
    # The stability suite alone (issue 5): hard cases, thresholds by bisection (~2-15 min).
    local out="$BUILD/stability" status=0
    rm -rf "$out/rows" "$out/stability.md"
    ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS" -L stability --timeout 900 || status=$?
    [ -f "$out/stability.md" ] && { cat "$out/stability.md"; say "table: $out/stability.md (runs in $out/runs)"; }
    return "$status"
  fi
  if [ "${1:-}" = "--cluster" ]; then
    ctest --test-dir "$BUILD" --output-on-failure -L cluster --timeout 900
    return
  fi
  [ $# -eq 0 ] || die "usage: ./fsi test [--stability|--cluster]"
  # ctest -j starts the tests it knows to be longest first, from the timings of the build's last
  # run; a clean clone has none, so it gets the committed ones (tests/ctest-costs.txt, the tests
  # of 5 s or more on the 2-core machine), or the long classes start last and one core idles.
  local costs="$BUILD/Testing/Temporary/CTestCostData.txt"
  if [ ! -f "$costs" ]; then
    mkdir -p "$(dirname "$costs")" && cp "$ROOT/tests/ctest-costs.txt" "$costs"
  fi
  ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS" -LE stability --timeout 900
  local fuzz_seconds=${FSI_FUZZ_SECONDS:-20}
  if [ "$fuzz_seconds" != "0" ]; then
    # The case parser's corpus is replayed by ctest (label fuzz); fuzzing it needs the whole
    # solver built with clang, which is ./fsi fuzz's.
    say "fuzzing the message decoder and the coupler's message handling ($fuzz_seconds s each; ./fsi fuzz: longer, and the case parser)"
    cmd_fuzz --seconds "$fuzz_seconds" envelope coupler_channel
  fi
  if [ "${FSI_SANITIZE:-1}" != "0" ]; then
    say "sanitizer pass (AddressSanitizer + UndefinedBehaviorSanitizer) of the structure tests"
    # -O1, no debug info: the CGAL-heavy sources compile in 0.58 of the time of -O3 with the
    # sanitizers (OrientedMesh.cpp: 33 s against 57 s), and -O1 is what AddressSanitizer advises.
    build "$ROOT/build-sanitize" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
      -DFSI_SANITIZE=ON -DFSI_BUILD_BENCH=OFF \
      -- fsi-structure test_common test_motion test_structure test_geometry test_collision test_output
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
      ctest --test-dir "$ROOT/build-sanitize" --output-on-failure -j "$JOBS" -L structure --timeout 1800
  fi
}

# libFuzzer (clang-14) over the fuzz targets of tests/fuzz, each from its committed seed corpus
# and past crashers; new inputs are kept in build-fuzz/corpus/<target> for the next session.
FUZZ_TARGETS=(envelope coupler_channel case_file)
cmd_fuzz() {
  local seconds=300 targets=() status=0
  while [ $# -gt 0 ]; do
    case "$1" in
      --seconds) [ $# -ge 2 ] || die "--seconds needs a number"; seconds=$2; shift 2 ;;
      --seconds=*) seconds=${1#--seconds=}; shift ;;
      -*) die "unknown option '$1' (usage: ./fsi fuzz [--seconds N] [TARGET ...])" ;;
      *) [[ " ${FUZZ_TARGETS[*]} " == *" $1 "* ]] || die "unknown fuzz target '$1' (targets: ${FUZZ_TARGETS[*]})"
         targets+=("$1"); shift ;;
    esac
  done
  [[ "$seconds" =~ ^[0-9]+$ ]] || die "--seconds takes whole seconds, not '$seconds'"
  [ ${#targets[@]} -gt 0 ] || targets=("${FUZZ_TARGETS[@]}")
  ensure_packages clang-14 libclang-rt-14-dev
  local dir="$ROOT/build-fuzz" built=()
  for t in "${targets[@]}"; do built+=("fuzz_$t"); done
  build "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFSI_FUZZ=ON -DFSI_BUILD_BENCH=OFF \
    -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 -- "${built[@]}"
  for t in "${targets[@]}"; do
    local corpus="$dir/corpus/$t" crashes="$dir/crashes/$t/" seeds="$ROOT/tests/fuzz/corpus/$t"
    local crashers="$ROOT/tests/fuzz/crashers/$t"
    mkdir -p "$corpus" "$crashes"
    local inputs=("$corpus" "$seeds")
    [ -d "$crashers" ] && inputs+=("$crashers")
    say "fuzzing $t for $seconds s (log: $dir/fuzz-$t.log)"
    if "$dir/bin/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$crashes" \
         -print_final_stats=1 "${inputs[@]}" >"$dir/fuzz-$t.log" 2>&1; then
      say "  $(grep -E '^Done [0-9]+ runs' "$dir/fuzz-$t.log" | tail -1): no crash"
    else
      # libFuzzer's own report (not the Protobuf parser's complaints about the inputs it is fed)
      grep -v "libprotobuf" "$dir/fuzz-$t.log" | grep -E "==ERROR|ERROR: libFuzzer|runtime error|SUMMARY|deadly signal|timeout|out-of-memory|Test unit written|^    #[0-9]" | head -30 >&2
      local unit
      unit=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$dir/fuzz-$t.log" | tail -1)
      # A time or memory limit hit by an input that passes when replayed alone is the machine
      # (a stalled VM), not the code: said, kept, not failed. Anything else fails.
      if grep -qE "ERROR: libFuzzer: (timeout|out-of-memory)" "$dir/fuzz-$t.log" && [ -n "$unit" ] &&
         "$dir/bin/fuzz_$t" -timeout=10 -rss_limit_mb=2048 "$unit" >"$dir/replay-$t.log" 2>&1; then
        say "  $t: an input hit libFuzzer's time or memory limit but passes when replayed alone ($unit,"
        say "  log $dir/replay-$t.log): a stall of this machine, not counted as a failure"
      else
        status=1
        say "  $t: a failing input is in $crashes; copy it into tests/fuzz/crashers/$t/ (a regression test) and fix"
      fi
    fi
  done
  return "$status"
}

cmd_bench() {
  prepare
  local which=${1:-structure}
  case "$which" in
    structure) shift || true; "$BUILD/bin/bench_structure" --benchmark_counters_tabular=true "$@" ;;
    transport) shift || true; "$BUILD/bin/bench_transport" --benchmark_counters_tabular=true "$@" ;;
    coupling) shift || true; "$BUILD/bin/bench_coupling" "$@" ;;
    fluid) shift || true; /usr/bin/python3 "$ROOT/bench/fluid/bench_fluid.py" --bin-dir "$BUILD/bin" "$@" ;;
    pump) shift || true; /usr/bin/python3 "$ROOT/bench/pump/bench_pump.py" --bin-dir "$BUILD/bin" "$@" ;;
    pump_rag) shift || true; /usr/bin/python3 "$ROOT/bench/pump/bench_rag_cost.py" --bin-dir "$BUILD/bin" "$@" ;;
    mpi_coupling) shift || true; /usr/bin/python3 "$ROOT/bench/fluid/bench_mpi_coupling.py" --bin-dir "$BUILD/bin" "$@" ;;
    mesh_surface|kernel_stencil|body_indicator|free_passage) shift || true; "$BUILD/bin/bench_$which" "$@" ;;
    *) die "unknown benchmark '$which' (available: structure, transport, coupling, fluid, pump, pump_rag, mpi_coupling, mesh_surface, kernel_stencil, body_indicator, free_passage)" ;;
  esac
}

case "${1:-help}" in
  run) shift; cmd_run "$@" ;;
  check) shift; cmd_check "$@" ;;
  test) shift; cmd_test "$@" ;;
  bench) shift; cmd_bench "$@" ;;
  schema) prepare fsi-structure; "$BUILD/bin/fsi-structure" --schema ;;
  build) prepare ;;
  report) shift; prepare; /usr/bin/python3 -m fsi.report --bin-dir "$BUILD/bin" --out "$ROOT/report" "$@" ;;
  pump-design)
    shift; [ $# -ge 1 ] || die "usage: ./fsi pump-design DESIGN.yaml [--write DIR] (e.g. pump/designs/single-blade.yaml)"
    prepare fsi-pump-design; "$BUILD/bin/fsi-pump-design" "$@" ;;
  pump-curve)
    shift; [ $# -ge 1 ] || die "usage: ./fsi pump-curve [--points F,F,...] [--jobs N] [--resolution NAME] CASE_DIR"
    prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.pump_curve --bin-dir "$BUILD/bin" "$@" ;;
  rag-ensemble)
    shift; [ $# -ge 1 ] || die "usage: ./fsi rag-ensemble [--runs N] [--seed S] [--flow-fraction F] [--sizes LxW,...] [--jobs N] CASE_DIR"
    prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.rag_ensemble --bin-dir "$BUILD/bin" "$@" ;;
  feed-compare)
    shift; [ $# -ge 1 ] || die "usage: ./fsi feed-compare [--designs A.yaml,B.yaml] [--flow-fractions F,...] [--seeds N] [--rags N] [--jobs N] [--submit] CASE_DIR"
    prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.feed_compare --bin-dir "$BUILD/bin" "$@" ;;
  coupling-study)
    shift; prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.coupling_study --bin-dir "$BUILD/bin" "$@" ;;
  disc-study)
    shift; prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.disc_study --bin-dir "$BUILD/bin" "$@" ;;
  ercoftac-study)
    shift; prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.ercoftac_study --bin-dir "$BUILD/bin" "$@" ;;
  pump-compare)
    shift; [ $# -ge 1 ] || die "usage: ./fsi pump-compare [--flow-fraction F] [--revolutions N] [--ranks N] [--from DIR] CASE_DIR"
    prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.pump_compare --bin-dir "$BUILD/bin" "$@" ;;
  fuzz) shift; cmd_fuzz "$@" ;;
  submit)
    shift; [ $# -ge 1 ] || die "usage: ./fsi submit [--partition P] [--time T] [--fluid-nodes N] [--dry-run] CASE_DIR [CASE_DIR ...]"
    prepare "${RUN_TARGETS[@]}"; /usr/bin/python3 -m fsi.fsi_submit --bin-dir "$BUILD/bin" "$@" ;;
  keys)
    shift; [ $# -ge 1 ] || die "usage: ./fsi keys [--force] CASE_DIR"
    prepare fsi-coupler; "$BUILD/bin/fsi-coupler" --make-keys "$@" ;;
  help|-h|--help) sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//' ;;
  *) die "unknown command '$1' (commands: run, submit, check, keys, test, fuzz, bench, report, schema, pump-design, pump-curve, pump-compare, rag-ensemble, feed-compare, coupling-study, disc-study, ercoftac-study, build, help)" ;;
esac
