# The two quick-start commands: `make demo` and `make test`. Binaries land in build/.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO_OUT ?= results/aps3

.PHONY: all deps build demo test sanitize bench format clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/cablesim run examples/aps3.yaml -o $(DEMO_OUT) --plots --report

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCS_SANITIZE=ON -DCMAKE_C_COMPILER=clang
	cmake --build build-asan -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1 ctest --test-dir build-asan --output-on-failure -j $(JOBS)

format:
	clang-format -i include/cablesim/*.h src/*.c src/*.h src/io/*.c src/io/*.h app/*.c tests/*.c tests/*.h examples/*.c 2>/dev/null || true

clean:
	rm -rf $(BUILD) build-asan
