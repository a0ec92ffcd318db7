#!/usr/bin/env bash
# Runs every fuzzer of BUILD_DIR for SECONDS each, FUZZ_JOBS (default 2) at a time, on its
# seed corpus (fuzz/seed_corpus.sh, in BUILD_DIR/corpus/) with its dictionary. Prints one
# line per fuzzer (executions per second, coverage); fails if any fuzzer found a crash, a
# leak, a timeout or an out-of-memory input, and prints its report and the input's path.
# usage: fuzz/run_fuzzers.sh BUILD_DIR SECONDS [FUZZER...]
set -euo pipefail

build=$(cd "${1:?usage: run_fuzzers.sh BUILD_DIR SECONDS [FUZZER...]}" && pwd)
seconds=${2:?usage: run_fuzzers.sh BUILD_DIR SECONDS [FUZZER...]}
shift 2
fuzz_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
jobs=${FUZZ_JOBS:-2}
fuzzers=("$@")
if [[ ${#fuzzers[@]} -eq 0 ]]; then
  fuzzers=(fuzz_xyz fuzz_xyz_exact fuzz_query fuzz_npy fuzz_spline fuzz_spline_exact fuzz_surface
           fuzz_off fuzz_obj fuzz_ply fuzz_stl)
fi

# A report of undefined behaviour with its stack, like ASan's.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

"$fuzz_dir"/seed_corpus.sh "$build/corpus"
mkdir -p "$build/logs"

run() { # run FUZZER: one fuzzing session; its exit status goes to logs/FUZZER.status
  local name=$1 dict max_len=8192
  case $name in
    fuzz_xyz* | fuzz_query) dict=xyz ;;
    fuzz_spline*) dict=spline max_len=16384 ;; # a degree-5 patch line takes ~1 kB
    fuzz_surface) dict=surface max_len=16384 ;;
    *) dict=${name#fuzz_} ;;
  esac
  mkdir -p "$build/artifacts/$name"
  local status=0
  # A reader must refuse bad input with Invalid_input in well under a second, and never
  # need gigabytes: a 10 s input or 2 GB of memory is a finding.
  # FUZZ_SEED fixes libFuzzer's random choices (CI): a run then explores the same inputs
  # on every machine, up to how many fit in the time.
  "$build/$name" ${FUZZ_SEED:+-seed="$FUZZ_SEED"} -max_total_time="$seconds" -rss_limit_mb=2048 \
    -timeout=10 -max_len=$max_len \
    -dict="$fuzz_dir/dict/$dict.dict" -artifact_prefix="$build/artifacts/$name/" \
    -print_final_stats=1 "$build/corpus/$name" >"$build/logs/$name.log" 2>&1 || status=$?
  echo $status >"$build/logs/$name.status"
}

for name in "${fuzzers[@]}"; do
  [[ -x $build/$name ]] || { echo "run_fuzzers.sh: no fuzzer $build/$name" >&2; exit 2; }
done
echo "fuzzing ${#fuzzers[@]} readers for ${seconds} s each, $jobs at a time (logs: $build/logs/)"
for name in "${fuzzers[@]}"; do
  while [[ $(jobs -rp | wc -l) -ge $jobs ]]; do wait -n || true; done
  run "$name" &
done
wait

failed=0
for name in "${fuzzers[@]}"; do
  log=$build/logs/$name.log
  status=$(cat "$build/logs/$name.status")
  # The last status line: "#N DONE cov: C ft: F corp: ... exec/s: E rss: R".
  summary=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -n 1 || true)
  execs=$(sed -n 's/^stat::average_exec_per_sec:[[:space:]]*//p' "$log")
  printf '%-18s %s  exec/s %s  %s\n' "$name" "$([[ $status == 0 ]] && echo ok || echo FAILED)" \
    "${execs:-?}" "$(grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[^ ]+' <<<"$summary" || true)"
  if [[ $status != 0 ]]; then
    failed=1
    echo "---- $name: exit status $status, report (from $log):"
    # From the first line of the report (sanitizer, libFuzzer, uncaught exception) on.
    report='^==[0-9]*==\|^ERROR: libFuzzer\|^SUMMARY\|terminate called\|runtime error'
    sed -n "/$report/,\$p" "$log" | grep -v '^#\|^stat::' | head -n 60
    echo "---- input: $(sed -n 's/.*Test unit written to //p' "$log" | tail -n 1)"
  fi
done
exit $failed
