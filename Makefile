# accsim front end. Every target installs what is missing first and is idempotent.
BUILD_DIR ?= build
SAN_DIR   ?= build-asan
JOBS      ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps venv configure build demo test bench sanitize clean help

all: build

help:
	@echo "make          build everything; the CLI lands in $(BUILD_DIR)/bin/accsim"
	@echo "make demo     the main job with bundled defaults"
	@echo "make test     build and run every test (ctest, then pytest)"
	@echo "make bench    print the benchmarks (accsim bench, Google Benchmark)"
	@echo "make sanitize build with ASan/UBSan and run the C++ tests"

deps:
	@bash scripts/install-deps.sh

venv: deps
	@bash scripts/make-venv.sh

$(BUILD_DIR)/build.ninja: | deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > /dev/null

configure: $(BUILD_DIR)/build.ninja

build: deps configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@bash scripts/demo.sh $(BUILD_DIR)

test: build venv
	@bash scripts/run-tests.sh $(BUILD_DIR)

bench: build venv
	@$(BUILD_DIR)/bin/accsim bench
	@$(BUILD_DIR)/bin/accsim_benchmarks --benchmark_min_time=0.2
	@if [ -f scripts/bench-python.sh ]; then bash scripts/bench-python.sh; fi

sanitize: deps
	@cmake -S . -B $(SAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACCSIM_SANITIZE=ON -DACCSIM_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(SAN_DIR) -j $(JOBS)
	@cd $(SAN_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR) $(SAN_DIR)
