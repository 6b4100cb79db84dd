# The two quick-start commands: `make demo` and `make test`. Binaries land in build/.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO_OUT ?= results/aps3

FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz

.PHONY: all deps configure build demo designer test sanitize fuzz fuzz-build fuzz-seeds fuzz-loader fuzz-engine \
  fuzz-sweep fuzz-set pin bench figures docs package format clean

all: build

deps:
	@bash scripts/install-deps.sh

# Configured again each time, so that packages installed since (cmocka, emscripten) are found.
configure:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: deps configure
	cmake --build $(BUILD) -j $(JOBS)

# Only what the demo needs: the command and its report page (no test toolchain, no tests built).
demo:
	@bash scripts/install-deps.sh --demo
	$(MAKE) --no-print-directory configure
	cmake --build $(BUILD) -j $(JOBS) --target cablesim_cmd
	$(BUILD)/cablesim run examples/aps3.yaml -o $(DEMO_OUT) --plots --report

# designer.html for the APS3 example (docs/designer.md): the page that runs it in the browser. The build
# makes its engine as WebAssembly where emscripten is installed (make deps installs it).
designer: build
	$(BUILD)/cablesim designer examples/aps3.yaml -o results/aps3-designer

# The whole suite, then the sanitized suite, then each fuzzer for FUZZ_SECONDS (docs/testing.md: what each
# part runs).
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	$(MAKE) --no-print-directory sanitize
	$(MAKE) --no-print-directory fuzz

# The sanitized suite: clang's AddressSanitizer + UBSan (Debug, $(SAN_BUILD)/), LeakSanitizer on, over the C
# code: every unit test (ctest label unit) and every shell test of the command (label script). Under the
# sanitizers a script runs its representative case of each kind of run (a run, a sweep, a stop and resume,
# validate's parts, a comparison...) and leaves the repeats of that kind to the plain suite
# (CS_TEST_SANITIZED=1, tests/lib.sh's plain_only): the sanitizers find a memory error on the path a case
# takes, not on its hundredth repeat. Left to the plain suite: the checks of the source tree, the pages in
# the browser, the installed tree and Debian packages, and the API reference (labels source, browser,
# install, docs), which run no C of this project's or run it as the scripts do. It builds only what it
# runs (the target test_programs) and compiles the report and designer pages $(BUILD) made (CS_PAGES_FROM)
# rather than making them again.
SAN_BUILD ?= build-asan
sanitize: deps
	@[ -f $(BUILD)/CMakeCache.txt ] || $(MAKE) --no-print-directory configure
	cmake --build $(BUILD) -j $(JOBS) --target pages
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCS_SANITIZE=ON -DCMAKE_C_COMPILER=clang \
	  -DCS_PAGES_FROM=$(abspath $(BUILD))
	cmake --build $(SAN_BUILD) -j $(JOBS) --target test_programs
	ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/fuzz/lsan.supp \
	  ctest --test-dir $(SAN_BUILD) --output-on-failure -j $(JOBS) -L '^(unit|script)$$'

# libFuzzer, each target built with ASan + UBSan + coverage and run for FUZZ_SECONDS:
# - fuzz/fuzz_loader.c, the model loader: seeded at run time from examples/, tests/good/, tests/bad/ (also
#   each example with --set lines), replaying tests/fuzz-regressions/;
# - fuzz/fuzz_engine.c, the engine: random valid designs (tests/design.h) run to their end, replaying
#   tests/fuzz-regressions/engine/ (its kept inputs, bytes, not YAML);
# - fuzz/fuzz_sweep.c, the sweep spec: seeded from the example studies;
# - fuzz/fuzz_set.sh, `cablesim check` (the sanitized one where make sanitize built it) with --set of
#   every numeric field at extreme values: exit status 0 or 2, every message at a place, none over 20 s.
# Each corpus grows in $(FUZZ_BUILD)/corpus-TARGET; a crash lands in $(FUZZ_BUILD)/artifacts.
FUZZ_CFLAGS = -std=c17 -Wall -Wextra -Wpedantic -Werror -O1 -g -fno-omit-frame-pointer -fno-sanitize-recover=all \
  -fsanitize=fuzzer,address,undefined -Iinclude -Isrc -Isrc/io -Itests -DCS_SOURCE_DIR='"$(CURDIR)"'
FUZZ_LIBS = $(FUZZ_BUILD)/libcablesim.a $$(pkg-config --libs yaml-0.1 json-c) -ludunits2 -lm -ldl
FUZZ_SET_CS = $(if $(wildcard $(SAN_BUILD)/cablesim),$(SAN_BUILD)/cablesim,$(BUILD)/cablesim)
FUZZ_RUN = LSAN_OPTIONS=suppressions=$(CURDIR)/fuzz/lsan.supp
FUZZ_FLAGS = -max_total_time=$(FUZZ_SECONDS) -timeout=20 -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/artifacts/

fuzz-build: deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_SANITIZE=ON -DCMAKE_C_COMPILER=clang -DCS_DESIGNER=OFF \
	  -DCMAKE_C_FLAGS=-fsanitize=fuzzer-no-link
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target cablesim_static
	for t in loader engine sweep; do \
	  clang $(FUZZ_CFLAGS) fuzz/fuzz_$$t.c $(FUZZ_LIBS) -o $(FUZZ_BUILD)/fuzz_$$t || exit 1; done

# The four fuzzers, FUZZ_JOBS at a time (by default as many as the cores): each runs FUZZ_SECONDS of wall
# time whatever runs beside it; make prints each one's log whole when it ends (--output-sync).
FUZZ_JOBS ?= $(JOBS)
FUZZ_RUNS = fuzz-loader fuzz-engine fuzz-sweep fuzz-set

fuzz: fuzz-build
	$(MAKE) --no-print-directory --output-sync=target -j $(FUZZ_JOBS) $(FUZZ_RUNS)

fuzz-seeds:
	rm -rf $(FUZZ_BUILD)/seeds $(FUZZ_BUILD)/seeds-sweep
	mkdir -p $(FUZZ_BUILD)/seeds $(FUZZ_BUILD)/seeds-sweep $(FUZZ_BUILD)/artifacts
	mkdir -p $(FUZZ_BUILD)/corpus-loader $(FUZZ_BUILD)/corpus-engine $(FUZZ_BUILD)/corpus-sweep
	for f in examples/*.yaml examples/roadside/*.yaml tests/good/*.yaml tests/bad/*.yaml; do \
	  cp "$$f" "$(FUZZ_BUILD)/seeds/$$(echo "$$f" | tr / -)"; done
	for f in examples/*.yaml; do \
	  { cat "$$f"; printf '#set scenario.speed=35 mph\n#set barrier.cables[0].pretension=8 kip\n'; \
	    printf '#set barrier.posts[0].spacing=6 ft\n#set vehicle=M\n'; } > "$(FUZZ_BUILD)/seeds/set-$${f##*/}"; done
	cp examples/aps3-uncertain.yaml $(FUZZ_BUILD)/seeds-sweep/
	sed 's|^model: design.yaml|model: roadside/design.yaml|' examples/roadside/spacing-study.yaml \
	  > $(FUZZ_BUILD)/seeds-sweep/spacing-study.yaml

fuzz-loader: fuzz-seeds
	$(FUZZ_RUN) $(FUZZ_BUILD)/fuzz_loader $(FUZZ_FLAGS) -dict=fuzz/loader.dict \
	  $(FUZZ_BUILD)/corpus-loader $(FUZZ_BUILD)/seeds $(wildcard tests/fuzz-regressions)

fuzz-engine: fuzz-seeds
	$(FUZZ_RUN) $(FUZZ_BUILD)/fuzz_engine $(FUZZ_FLAGS) $(FUZZ_BUILD)/corpus-engine tests/fuzz-regressions/engine

fuzz-sweep: fuzz-seeds
	$(FUZZ_RUN) $(FUZZ_BUILD)/fuzz_sweep $(FUZZ_FLAGS) -dict=fuzz/loader.dict \
	  $(FUZZ_BUILD)/corpus-sweep $(FUZZ_BUILD)/seeds-sweep tests/fuzz-regressions/sweep

fuzz-set: fuzz-seeds
	$(FUZZ_RUN) bash fuzz/fuzz_set.sh $(FUZZ_SET_CS) $(FUZZ_SECONDS)

# The pinned runs, rewritten from this engine: the one way to change them (tests/example.h). Built with
# musl's maths in $(BUILD) (CS_MATH=musl: the numbers of tests/predictions/*.csv, the hashes and the
# outputs of tests/golden/musl/) and with glibc's in $(PIN_GLIBC) (their own hashes and tests/golden/glibc/,
# on a processor with FMA and AVX2). Then review and commit the diff it prints.
PIN_GLIBC ?= build-glibc
PIN_TESTS = test_io_crash_tests test_io_roadside test_io_golden

pin: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_MATH=musl
	cmake -S . -B $(PIN_GLIBC) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_MATH=glibc -DCS_REPORT=OFF -DCS_DESIGNER=OFF
	for b in $(BUILD) $(PIN_GLIBC); do \
	  cmake --build $$b -j $(JOBS) --target cablesim_cmd $(PIN_TESTS) || exit 1; \
	  for t in $(PIN_TESTS); do \
	    CS_PIN_UPDATE=1 $$b/$$t >$$b/$$t.pin.log 2>&1 || { cat $$b/$$t.pin.log; exit 1; }; \
	    grep '^pinned: ' $$b/$$t.pin.log; done; done
	git diff --stat -- tests/predictions tests/golden
	git status --short -- tests/golden

# Benchmarks (bench/run.sh, docs/performance.md; not part of test). Settings: BENCH_N (Monte Carlo runs, 1000),
# BENCH_T_END (end time of the APS3 runs; empty: the model's), BENCH_POSTS, BENCH_POSTS_T_END, BENCH_REPEAT.
bench: build
	BUILD=$(BUILD) bash bench/run.sh

# docs/roadside-spacing.png and docs/study-page.png, the guide's figures a run draws, by this build
# (scripts/docs-figures.sh).
figures: build
	bash scripts/docs-figures.sh $(BUILD)

# The Debian packages (debian/, debhelper) in $(BUILD)/deb: libcablesim1, libcablesim-dev, cablesim and
# cablesim-data, for `apt install ./$(BUILD)/deb/*.deb`.
package: deps
	DEB_BUILD_OPTIONS="parallel=$(JOBS) $(DEB_BUILD_OPTIONS)" bash scripts/build-deb.sh $(BUILD)/deb

# The API reference from the public headers (Doxygen): $(BUILD)/docs/html/index.html.
docs: deps configure
	cmake --build $(BUILD) --target docs

format:
	clang-format -i include/cablesim/*.h src/*/*.c src/*/*.h src/io/*/*.c src/io/*/*.h app/*.c tests/*.c tests/*.h examples/*.c examples/*/*.c fuzz/*.c 2>/dev/null || true

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(FUZZ_BUILD) $(PIN_GLIBC)
