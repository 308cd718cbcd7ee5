# povml — set-up, build, render, test, benchmark.
# `make render` and `make test` install whatever Debian packages are missing first.

DEB_PACKAGES = libcamlimages-ocaml-dev libjpeg-dev libalcotest-ocaml-dev \
               libcmdliner-ocaml-dev libqcheck-ocaml-dev povray povray-includes povray-examples time parallel \
               slurm-wlm munge openssh-server rsync

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
POVML = ./_build/default/bin/main.exe

.PHONY: all deps build install render test test-slurm test-ssh fuzz bench report samples animations references clean

all: build

# Install only the packages that are missing (dpkg-query answers quickly; apt-get runs only if needed).
deps:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -q && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q $$missing; \
	fi
	@mkdir -p $$HOME/.povray/3.7 && touch $$HOME/.povray/3.7/povray.conf

# The release profile: dune's dev profile compiles with -opaque, which stops inlining across
# modules (every shape is a module of its own). The tests build in the dev profile, where warnings
# are errors.
build: deps
	dune build --profile release

PREFIX ?= /usr/local
install: build
	dune install --profile release --prefix $(PREFIX)

render: build
	$(POVML) +Iscenes/showcase.pov +Oshowcase.png +W640 +H480 +A0.3 -D
	@echo "The showcase scene is in $$(pwd)/showcase.png"

test: deps
	dune build
	dune test --force

# The README's Slurm recipe on a one-node Slurm started on this machine (test/slurm; needs root).
test-slurm: deps
	dune build
	bash test/slurm/run.sh

# The README's GNU parallel recipe across machines (--sshlogin) with a second machine made on this
# one: an sshd on 127.0.0.1 for an account of its own (test/ssh/run.sh; needs root).
test-ssh: deps
	dune build
	bash test/ssh/run.sh

# AFL++ on the interpreter and a tiny render for FUZZ_SECONDS (test/fuzz/afl.sh), built instrumented in
# _build_afl (test/fuzz/afl.workspace); prints the inputs tried and fails on any crash or hang.
FUZZ_SECONDS ?= 1800
# then AFL++ on each image decoder and the TrueType reader for FUZZ_IMAGE_SECONDS each (test/fuzz/afl_images.sh)
FUZZ_IMAGE_SECONDS ?= 300
fuzz: deps
	@dpkg-query -W -f='$${Status}' afl++ 2>/dev/null | grep -q "install ok installed" || { \
	  echo "Installing Debian packages: afl++"; \
	  $(SUDO) apt-get update -q && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q afl++; }
	dune build --workspace test/fuzz/afl.workspace --build-dir _build_afl \
	  ./test/fuzz/afl_main.exe ./test/fuzz/povml.dict ./test/fuzz/afl_image.exe
	FUZZ_SECONDS=$(FUZZ_SECONDS) bash test/fuzz/afl.sh
	FUZZ_IMAGE_SECONDS=$(FUZZ_IMAGE_SECONDS) bash test/fuzz/afl_images.sh

bench: build
	bash scenes/bench/run.sh

# Error against time of povml and POV-Ray on bench scenes: the plot in the README (docs/report).
report: build
	$(POVML) report scenes/bench/spheres.pov scenes/bench/generated/spheres_10000.pov \
	  scenes/bench/while_spheres.pov --out docs/report +W320 +H240 --runs 2 \
	  --thresholds 0.9,0.6,0.3,0.2,0.1,0.0 --trace-levels 1-10

# Every scene of POV-Ray's sample set (povray-examples) rendered with povml and with POV-Ray at 160×120:
# docs/samples.md and docs/samples.tsv (test/samples/run.sh). 5 to 10 minutes on 2 cores; not part of `make test`.
# SAMPLES_JOBS=N scenes at a time (default 2); ONLY=regex for a subset (written under /tmp, not docs/).
samples: build
	bash test/samples/run.sh

# POV-Ray's sample animations from their .ini files, frame for frame against POV-Ray (docs/animations.md).
animations: build
	dune build --profile release test/tools/imgdiff.exe
	bash test/samples/animations.sh

references: deps
	bash reference/regen.sh

clean:
	dune clean
	rm -rf _build_afl _fuzz
