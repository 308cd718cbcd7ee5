#!/usr/bin/env bash
# make fuzz, second part: AFL++ on each decoder (test/fuzz/afl_image.exe FORMAT FILE, built
# instrumented by the Makefile in _build_afl) for FUZZ_IMAGE_SECONDS each, seeded with the files of
# test/fuzz/image_seeds/<format>/ (POT with the GIF files; TrueType with POV-Ray's own fonts) and the
# corpus earlier runs grew from them, test/fuzz/image_corpus/<format>/ (minimised with afl-cmin; to
# refresh it: afl-cmin -i $FUZZ_OUT/images/<format>/default/queue -o test/fuzz/image_corpus/<format>
# -- _build_afl/default/test/fuzz/afl_image.exe <format> @@).
# Prints how many inputs each tried and fails if any input crashed or hung.
#   FUZZ_IMAGE_SECONDS  how long to fuzz each decoder (default 300)
#   FUZZ_IMAGE_FORMATS  which decoders (default: png gif pot jpeg ppm pgm tga ttf)
#   FUZZ_OUT            AFL++'s output directory (default _fuzz, git-ignored); images/<format> in it
#   FUZZ_TIMEOUT        milliseconds one input may take before it counts as a hang (default 2000)
set -euo pipefail
cd "$(dirname "$0")/../.."

seconds=${FUZZ_IMAGE_SECONDS:-300}
formats=${FUZZ_IMAGE_FORMATS:-png gif pot jpeg ppm pgm tga ttf}
out=${FUZZ_OUT:-_fuzz}/images
timeout=${FUZZ_TIMEOUT:-2000}
target=_build_afl/default/test/fuzz/afl_image.exe
fonts=/usr/share/povray-3.7/include

# As in afl.sh: no CPU governor in a container, core dumps to a file, any free core, OCaml's 64 KiB
# map; -m: 2 GiB of address space an input, well above the target's caps (64 MiB of samples).
export AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_AFFINITY=1 AFL_NO_UI=1
export AFL_MAP_SIZE=65536

failed=0
for format in $formats; do
  dir=$out/$format
  rm -rf "$dir"
  mkdir -p "$dir/seeds"
  case $format in
    pot) cp test/fuzz/image_seeds/gif/* "$dir/seeds/" ;;
    ttf) cp -L "$fonts/povlogo.ttf" "$fonts/crystal.ttf" "$dir/seeds/" ;;
    *) cp test/fuzz/image_seeds/"$format"/* "$dir/seeds/" ;;
  esac
  if [ -d test/fuzz/image_corpus/"$format" ]; then cp test/fuzz/image_corpus/"$format"/* "$dir/seeds/"; fi
  afl-fuzz -i "$dir/seeds" -o "$dir" -t "$timeout" -m 2048 -V "$seconds" \
    -- "$target" "$format" @@ > "$dir/afl-fuzz.log" 2>&1 || true
  stats=$dir/default/fuzzer_stats
  if [ ! -f "$stats" ]; then
    echo "make fuzz: $format: afl-fuzz did not start; the end of $dir/afl-fuzz.log:"; tail -20 "$dir/afl-fuzz.log"; failed=1; continue
  fi
  stat() { awk -F' *: *' -v k="$1" '$1 == k { print $2 }' "$stats"; }
  crashes=$(stat saved_crashes)
  hangs=$(stat saved_hangs)
  echo "make fuzz: $format: $(stat execs_done) inputs tried in $(stat run_time) s ($(stat execs_per_sec) a second)," \
    "$(stat corpus_count) in the corpus, $(stat edges_found) edges, $crashes crashes, $hangs hangs"
  if [ "$crashes" != 0 ] || [ "$hangs" != 0 ]; then
    echo "make fuzz: $format: the inputs are in $dir/default/crashes and $dir/default/hangs;" \
      "reproduce one with $target $format FILE"
    failed=1
  fi
done
exit $failed
