# accsim front end. Every target installs what is missing first and is idempotent.
BUILD_DIR ?= build
SAN_DIR   ?= build-sanitize
JOBS      ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps venv configure build demo test bench sanitize fuzz clean help

all: build

help:
	@echo "make          build everything; the CLI lands in $(BUILD_DIR)/bin/accsim"
	@echo "make demo     the main job with bundled defaults"
	@echo "make test     build and run every test (ctest, then pytest)"
	@echo "make bench    print the benchmarks (accsim bench, Google Benchmark)"
	@echo "make sanitize build with clang + ASan/UBSan and run the C++ tests and the extractor fuzzer"
	@echo "make fuzz     libFuzzer on the narrative extractor for FUZZ_SECONDS (clang, ASan/UBSan)"

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
	@CC=clang-14 CXX=clang++-14 cmake -S . -B $(SAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACCSIM_SANITIZE=ON \
	  -DACCSIM_BUILD_FUZZ=ON -DACCSIM_BUILD_BENCH=OFF -DACCSIM_BUILD_PYTHON=OFF > /dev/null
	@cmake --build $(SAN_DIR) -j $(JOBS)
	@cd $(SAN_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
fuzz: deps
	@CC=clang-14 CXX=clang++-14 cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACCSIM_SANITIZE=ON \
	  -DACCSIM_BUILD_FUZZ=ON -DACCSIM_BUILD_TESTS=OFF -DACCSIM_BUILD_BENCH=OFF -DACCSIM_BUILD_PYTHON=OFF > /dev/null
	@cmake --build $(FUZZ_DIR) --target accsim_fuzz_extractor -j $(JOBS)
	@mkdir -p $(FUZZ_DIR)/corpus && cp scenarios/examples/*.json $(FUZZ_DIR)/corpus/ 2>/dev/null || true
	@$(FUZZ_DIR)/bin/accsim_fuzz_extractor -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -timeout=10 $(FUZZ_DIR)/corpus fuzz/corpus

clean:
	rm -rf $(BUILD_DIR) $(SAN_DIR) $(FUZZ_DIR)
