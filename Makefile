# The two quick-start commands: `make demo` and `make test`. Binaries land in build/.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO_OUT ?= results/aps3

FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz

.PHONY: all deps build demo test sanitize fuzz fuzz-build bench docs package format clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/cablesim run examples/aps3.yaml -o $(DEMO_OUT) --plots --report

# The suite, then the same suite under AddressSanitizer + UBSan, then the loader's fuzzer for FUZZ_SECONDS.
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	$(MAKE) --no-print-directory sanitize
	$(MAKE) --no-print-directory fuzz

sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCS_SANITIZE=ON -DCMAKE_C_COMPILER=clang
	cmake --build build-asan -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/fuzz/lsan.supp \
	  ctest --test-dir build-asan --output-on-failure -j $(JOBS)

# libFuzzer on the model loader (fuzz/fuzz_loader.c): the loader built with ASan + UBSan + coverage, seeded
# at run time from examples/, tests/good/, tests/bad/ (also each example with --set lines) and replaying
# tests/fuzz-regressions/. The corpus grows in $(FUZZ_BUILD)/corpus; a crash lands in $(FUZZ_BUILD)/artifacts.
fuzz-build: deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_SANITIZE=ON -DCMAKE_C_COMPILER=clang \
	  -DCMAKE_C_FLAGS=-fsanitize=fuzzer-no-link
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target cablesim_static
	clang -std=c17 -Wall -Wextra -Wpedantic -Werror -O1 -g -fno-omit-frame-pointer -fno-sanitize-recover=all \
	  -fsanitize=fuzzer,address,undefined -Iinclude -Isrc/io -DCS_SOURCE_DIR='"$(CURDIR)"' \
	  fuzz/fuzz_loader.c $(FUZZ_BUILD)/libcablesim.a \
	  $$(pkg-config --libs yaml-0.1) -ludunits2 -lm -o $(FUZZ_BUILD)/fuzz_loader

fuzz: fuzz-build
	rm -rf $(FUZZ_BUILD)/seeds
	mkdir -p $(FUZZ_BUILD)/seeds $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/artifacts
	for f in examples/*.yaml examples/roadside/*.yaml tests/good/*.yaml tests/bad/*.yaml; do \
	  cp "$$f" "$(FUZZ_BUILD)/seeds/$$(echo "$$f" | tr / -)"; done
	for f in examples/*.yaml; do \
	  { cat "$$f"; printf '#set scenario.speed=35 mph\n#set barrier.cables[0].pretension=8 kip\n'; \
	    printf '#set barrier.posts[0].spacing=6 ft\n#set vehicle=M\n'; } > "$(FUZZ_BUILD)/seeds/set-$${f##*/}"; done
	LSAN_OPTIONS=suppressions=$(CURDIR)/fuzz/lsan.supp $(FUZZ_BUILD)/fuzz_loader -max_total_time=$(FUZZ_SECONDS) \
	  -timeout=10 -print_final_stats=1 -dict=fuzz/loader.dict -artifact_prefix=$(FUZZ_BUILD)/artifacts/ \
	  $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/seeds $(wildcard tests/fuzz-regressions)

# Benchmarks (bench/run.sh, docs/performance.md; not part of test). Settings: BENCH_N (Monte Carlo runs, 1000),
# BENCH_T_END (end time of the APS3 runs; empty: the model's), BENCH_POSTS, BENCH_POSTS_T_END, BENCH_REPEAT.
bench: build
	BUILD=$(BUILD) bash bench/run.sh

# The Debian package (CPack): $(BUILD)/cablesim_VERSION_ARCH.deb, for `apt install ./$(BUILD)/cablesim_*.deb`.
package: build
	cd $(BUILD) && cpack -G DEB

# The API reference from the public headers (Doxygen): $(BUILD)/docs/html/index.html.
docs: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) --target docs

format:
	clang-format -i include/cablesim/*.h src/*.c src/*.h src/io/*/*.c src/io/*/*.h app/*.c tests/*.c tests/*.h examples/*.c examples/*/*.c fuzz/*.c 2>/dev/null || true

clean:
	rm -rf $(BUILD) build-asan $(FUZZ_BUILD)
