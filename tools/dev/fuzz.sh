#!/usr/bin/env bash
# ochre fuzzing with libFuzzer (docs/validation.md, "Fuzzing"; docs/tools.md).
#
#   tools/dev/fuzz.sh TARGET HOURS [FINDINGS_DIR]   long run: fuzzes TARGET for HOURS (decimals allowed, e.g.
#                                               0.25), keeps going after a finding and saves every
#                                               crashing, leaking or hanging input in FINDINGS_DIR
#                                               (default build/fuzz/findings/TARGET); at the end replays
#                                               each and exits 1 when one reproduces
#   tools/dev/fuzz.sh --short TARGET SECONDS        short run as the test suite's fuzz.TARGET: stops at the
#                                               first finding (exit 1); exit 77 (skip) without clang-14
#   tools/dev/fuzz.sh --build                       configures and builds the fuzz tree only (exit 77 without
#                                               clang-14 / libFuzzer)
#   tools/dev/fuzz.sh --list                        the targets: scene material mesh csv envmap mitsuba python
#                                               arguments
#
# The target python is the Python module's driver tests/fuzz/fuzz_python.py (random arguments to every entry
# point, calls in child processes; no clang needed): it runs on the module of the normal build
# ($OCHRE_PYTHON_DIR, default build/python) with /usr/bin/python3, and logs to FINDINGS_DIR/fuzz.log.
# The target arguments is the programs' command-line driver tests/fuzz/fuzz_arguments.py (valid command lines
# of every program, mutated): it runs the programs of the normal build ($OCHRE_BIN_DIR, default build/bin).
#
# The fuzz tree (clang-14, -fsanitize=fuzzer,address,undefined, -O1) is build/fuzz, or
# $OCHRE_FUZZ_BUILD_DIR. A long run grows its corpus in build/fuzz/corpus/TARGET (kept between runs) from
# the seeds in tests/fuzz/corpus/TARGET, runs at nice 10 with $OCHRE_FUZZ_JOBS processes (default 1) and
# logs to FINDINGS_DIR/fuzz.log. Reproduce a finding with: build/fuzz/bin/fuzz_TARGET FILE, or without
# sanitizers with build/bin/fuzz_replay_TARGET FILE.
set -euo pipefail

SOURCE_DIR="$(cd "$(dirname "$0")/../.." && pwd)"
BUILD_DIR="${OCHRE_FUZZ_BUILD_DIR:-$SOURCE_DIR/build/fuzz}"
CXX_FUZZ="${OCHRE_FUZZ_CXX:-clang++-14}"
TARGETS="scene material mesh csv envmap mitsuba python arguments"
SKIP=77

usage() {
  sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

# A Python driver (python: the module's, arguments: the programs' command lines; docs/validation.md,
# "Fuzzing") for SECONDS; its report on stdout, or in LOG.
driver_run() {
  local target="$1" seconds="$2" log="${3:-}" status=0
  local -a command
  if [ "$target" = python ]; then
    local python_dir="${OCHRE_PYTHON_DIR:-$SOURCE_DIR/build/python}"
    if [ ! -d "$python_dir/ochre" ]; then
      echo "tools/dev/fuzz.sh: no Python module in $python_dir (build it: cmake --build build --target ochre_python)" >&2
      exit 2
    fi
    command=(env PYTHONPATH="$python_dir" /usr/bin/python3 "$SOURCE_DIR/tests/fuzz/fuzz_python.py")
  else
    local bin_dir="${OCHRE_BIN_DIR:-$SOURCE_DIR/build/bin}"
    if [ ! -x "$bin_dir/ochre" ]; then
      echo "tools/dev/fuzz.sh: no programs in $bin_dir (build them: cmake --build build)" >&2
      exit 2
    fi
    command=(/usr/bin/python3 "$SOURCE_DIR/tests/fuzz/fuzz_arguments.py" --bin "$bin_dir")
  fi
  if [ -z "$log" ]; then
    "${command[@]}" --seconds "$seconds"
    return
  fi
  mkdir -p "$(dirname "$log")"
  echo "tools/dev/fuzz.sh: fuzzing $target for $seconds s; log in $log"
  nice -n 10 "${command[@]}" --seconds "$seconds" >"$log" 2>&1 || status=$?
  tail -n 20 "$log"
  return $status
}

check_target() {
  case " $TARGETS " in
    *" $1 "*) ;;
    *) echo "tools/dev/fuzz.sh: unknown target '$1' (known: $TARGETS)" >&2; exit 2 ;;
  esac
}

# Exit 77 (the tests' skip code) when the compiler cannot build a libFuzzer program with sanitizers.
require_toolchain() {
  if ! command -v "$CXX_FUZZ" >/dev/null 2>&1; then
    echo "tools/dev/fuzz.sh: skipped: $CXX_FUZZ not found (tools/setup.sh installs clang-14 and libfuzzer-14-dev)"
    exit $SKIP
  fi
  local probe
  probe="$(mktemp -d)"
  echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' \
    >"$probe/probe.cpp"
  if ! "$CXX_FUZZ" -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" \
    >"$probe/log" 2>&1; then
    echo "tools/dev/fuzz.sh: skipped: $CXX_FUZZ cannot link -fsanitize=fuzzer,address,undefined" \
      "(libFuzzer / compiler-rt missing: install libfuzzer-14-dev and libclang-rt-14-dev)"
    rm -rf "$probe"
    exit $SKIP
  fi
  rm -rf "$probe"
}

build() {
  require_toolchain
  local launcher=()
  command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  if [ ! -f "$BUILD_DIR/build.ninja" ]; then
    # -O1: the sanitizers' usual level (fast to build, still fast to run); line tables for the reports.
    cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$CXX_FUZZ" -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" \
      -DOCHRE_FUZZ=ON -DOCHRE_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
  fi
  cmake --build "$BUILD_DIR" --target ochre_fuzzers -j "${OCHRE_FUZZ_BUILD_JOBS:-2}"
}

# libFuzzer options shared by short and long runs.
common_options() {
  local target="$1" dict="$SOURCE_DIR/tests/fuzz/dict/$1.dict"
  # 30 s per input is a hang; 2 GB is far beyond what a small input may need. Every finding exits 1
  # (libFuzzer's default 77 is the tests' skip code).
  echo "-timeout=${OCHRE_FUZZ_TIMEOUT:-30} -rss_limit_mb=2048 -max_len=${OCHRE_FUZZ_MAX_LEN:-16384}"
  echo "-error_exitcode=1 -timeout_exitcode=1"
  # OpenImageIO, Embree, TBB and Assimp keep per-process state, so that every input of these targets looks
  # like a leak to libFuzzer, whose leak check then costs 3/4 of the time.
  case "$target" in scene | mesh | envmap) echo "-detect_leaks=0" ;; esac
  [ -f "$dict" ] && echo "-dict=$dict"
  return 0
}

short_run() {
  local target="$1" seconds="$2"
  check_target "$target"
  case "$target" in python | arguments)
    driver_run "$target" "$seconds"
    return ;;
  esac
  local fuzzer="$BUILD_DIR/bin/fuzz_$target"
  if [ ! -x "$fuzzer" ]; then
    require_toolchain
    echo "tools/dev/fuzz.sh: $fuzzer is missing: the fuzz.build test (tools/dev/fuzz.sh --build) failed" >&2
    exit 1
  fi
  local work="$BUILD_DIR/short/$target" findings="$BUILD_DIR/findings/$target"
  rm -rf "$work"
  mkdir -p "$work" "$findings"
  # New inputs go to the scratch directory (first), never into the seed corpus in the source tree. A fixed
  # seed makes the run repeatable (a test failure reproduces), up to the number of inputs run in the time.
  # shellcheck disable=SC2046
  "$fuzzer" $(common_options "$target") -seed="${OCHRE_FUZZ_SEED:-1}" -max_total_time="$seconds" \
    -runs=1000000 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$work" "$SOURCE_DIR/tests/fuzz/corpus/$target"
}

long_run() {
  local target="$1" hours="$2"
  check_target "$target"
  local seconds
  seconds="$(awk -v h="$hours" 'BEGIN { s = int(h * 3600); if (s < 1) exit 1; print s }')" || {
    echo "tools/dev/fuzz.sh: HOURS must be a positive number (got '$hours')" >&2
    exit 2
  }
  case "$target" in python | arguments)
    driver_run "$target" "$seconds" "${3:-$BUILD_DIR/findings/$target}/fuzz.log"
    return ;;
  esac
  build
  local findings="${3:-$BUILD_DIR/findings/$target}" corpus="$BUILD_DIR/corpus/$target"
  mkdir -p "$findings" "$corpus"
  findings="$(cd "$findings" && pwd)"
  echo "tools/dev/fuzz.sh: fuzzing $target for $seconds s; findings in $findings, log in $findings/fuzz.log"
  local status=0
  # shellcheck disable=SC2046
  nice -n 10 "$BUILD_DIR/bin/fuzz_$target" $(common_options "$target") -max_total_time="$seconds" \
    -fork="${OCHRE_FUZZ_JOBS:-1}" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -artifact_prefix="$findings/" "$corpus" "$SOURCE_DIR/tests/fuzz/corpus/$target" \
    >"$findings/fuzz.log" 2>&1 || status=$?
  # Fork mode also saves the input a job was running when it was stopped: keep what reproduces alone.
  local count=0 file
  mkdir -p "$findings/not-reproduced"
  for file in "$findings"/crash-* "$findings"/leak-* "$findings"/timeout-* "$findings"/oom-*; do
    [ -f "$file" ] || continue
    # shellcheck disable=SC2046
    if "$BUILD_DIR/bin/fuzz_$target" $(common_options "$target") "$file" >"$file.log" 2>&1; then
      mv "$file" "$file.log" "$findings/not-reproduced/"
    else
      count=$((count + 1))
    fi
  done
  echo "tools/dev/fuzz.sh: $target: $count finding(s) that reproduce in $findings (replay logs beside them);" \
    "corpus $(ls "$corpus" | wc -l) inputs; libFuzzer exit $status"
  [ "$count" -eq 0 ]
}

case "${1:-}" in
  --build) [ $# -eq 1 ] || usage; build ;;
  --short) [ $# -eq 3 ] || usage; short_run "$2" "$3" ;;
  --list) echo "$TARGETS" ;;
  "" | -h | --help) usage ;;
  *) [ $# -ge 2 ] && [ $# -le 3 ] || usage; long_run "$@" ;;
esac
