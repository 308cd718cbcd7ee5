#!/usr/bin/env bash
# make fuzz: AFL++ on the instrumented target (built by the Makefile in _build_afl) for FUZZ_SECONDS,
# seeded with the small scenes of scenes/, test/fuzz/seeds and test/bad, with the language's words
# as its dictionary.
# Prints how many inputs were tried and fails if any input crashed or hung.
#   FUZZ_SECONDS   how long to fuzz (default 1800)
#   FUZZ_OUT       AFL++'s output directory (default _fuzz, git-ignored); each run starts afresh
#   FUZZ_TIMEOUT   milliseconds one input may take before it counts as a hang (default 2000)
set -euo pipefail
cd "$(dirname "$0")/../.."

seconds=${FUZZ_SECONDS:-1800}
out=${FUZZ_OUT:-_fuzz}
timeout=${FUZZ_TIMEOUT:-2000}
build=_build_afl/default/test/fuzz
target=$build/afl_main.exe
max_seed_bytes=8192

rm -rf "$out"
mkdir -p "$out/seeds"
# Seeds: every small scene but the benchmarks (their loops run for seconds on purpose), and the
# malformed scenes of test/bad.
find scenes test/fuzz/seeds test/bad -name '*.pov' -size -$((max_seed_bytes + 1))c -not -path 'scenes/bench/*' | sort |
  while read -r f; do cp "$f" "$out/seeds/$(echo "${f%.pov}" | tr / _).pov"; done
echo "make fuzz: $(ls "$out/seeds" | wc -l) seed scenes, $(wc -l < $build/povml.dict) dictionary words, $seconds s"

# A container has no CPU frequency governor to check and sends core dumps to a file (core_pattern
# "core"), which AFL++ refuses unless told that crashes may be reported late; the fuzzer runs on
# whichever core is free; OCaml's instrumentation writes a 64 KiB map, much smaller than AFL++'s
# default. -m: 2 GiB of address space an input, well above the target's memory limit (128 MiB).
# The afl-fuzz exit status is ignored: the statistics decide.
export AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_AFFINITY=1 AFL_NO_UI=1
export AFL_MAP_SIZE=65536
afl-fuzz -i "$out/seeds" -o "$out" -x $build/povml.dict -t "$timeout" -m 2048 -V "$seconds" \
  -- "$target" @@ > "$out/afl-fuzz.log" 2>&1 || true

stats=$out/default/fuzzer_stats
if [ ! -f "$stats" ]; then
  echo "make fuzz: afl-fuzz did not start; the end of $out/afl-fuzz.log:"; tail -20 "$out/afl-fuzz.log"; exit 2
fi
stat() { awk -F' *: *' -v k="$1" '$1 == k { print $2 }' "$stats"; }
crashes=$(stat saved_crashes)
hangs=$(stat saved_hangs)
echo "make fuzz: $(stat execs_done) inputs tried in $(stat run_time) s ($(stat execs_per_sec) a second)," \
  "$(stat corpus_count) in the corpus, $(stat edges_found) edges, $crashes crashes, $hangs hangs"
if [ "$crashes" != 0 ] || [ "$hangs" != 0 ]; then
  echo "make fuzz: the inputs are in $out/default/crashes and $out/default/hangs;" \
    "reproduce one with $target FILE"
  ls "$out/default/crashes" "$out/default/hangs"
  exit 1
fi
