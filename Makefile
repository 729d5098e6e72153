# The two commands of the README: `make demo` and `make test`. Both install missing Debian packages first.
# `make kitti00-loops` / `make kitti00`: loop detection / drift correction on all of KITTI 00 (object frames).
# The reliability checks (README "Reliability checks"): `make test-sanitize`, `make test-tsan` and `make fuzz`
# (`make fuzz-long` before a release), each a clang build in a directory of its own.
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?=
DEPS_FLAGS ?=
FUZZ_SECONDS ?= 60
FUZZ_HARNESSES ?=
TARGETS ?=
# Debug keeps assertions (Eigen's index checks among them); cmake/SgtllcSanitize.cmake then compiles at -O1.
# Debian's FAISS is a GCC-built static library (GNU OpenMP, no sanitizer instrumentation): the clang builds leave
# retrieval.method: ivf out, and its tests skip there.
CLANG_FLAGS = -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DSGTLLC_BUILD_BENCH=OFF -DSGTLLC_BUILD_PYTHON=OFF \
  -DSGTLLC_BUILD_EXAMPLES=OFF -DSGTLLC_WITH_FAISS=OFF
SGTLLC = $(BUILD)/apps/sgtllc/sgtllc
KITTI = data/kitti/00/velodyne
KITTI00 = $(BUILD)/kitti00
KITTI00_CONFIG = configs/kitti00-objects.yaml

.PHONY: all deps configure build demo test test-core bench test-sanitize test-tsan fuzz fuzz-long clean kitti00 kitti00-loops

all: build

deps:
	@./scripts/install-deps.sh $(DEPS_FLAGS)

# With ccache (install-deps.sh installs it), the module `pip install .` builds in build-pip/ (setup.py, and the
# python_pip_install test) reuses this build's objects instead of compiling the libraries a second time.
CCACHE_FLAG = $(if $(shell command -v ccache),-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CCACHE_FLAG) $(CMAKE_FLAGS) > $(BUILD).configure.log 2>&1 \
	  || (cat $(BUILD).configure.log; exit 1)

build: configure
	cmake --build $(BUILD) -j $(JOBS) $(if $(TARGETS),--target $(TARGETS))

# The demo and the KITTI 00 runs need only the command-line tool, not the tests and benchmarks of `make build`.
demo:
	@$(MAKE) --no-print-directory build TARGETS=sgtllc_cli
	@echo "== KITTI 00: frame 4501 revisits frame 52 (2.96 m apart, ground truth) =="
	@$(SGTLLC) pair $(KITTI)/004501.bin $(KITTI)/000052.bin
	@echo
	@echo "== KITTI 00: frame 850 vs frame 88 (309 m apart: not a loop) =="
	@$(SGTLLC) pair $(KITTI)/000850.bin $(KITTI)/000088.bin

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The 4,541 node files of KITTI 00 (data/README.md), unpacked once per change of the archive.
$(KITTI00)/objects.stamp: data/kitti/00/objects.tar.xz
	@mkdir -p $(KITTI00) && rm -rf $(KITTI00)/objects
	tar -xJf $< -C $(KITTI00)
	@touch $@

# Loop detection on KITTI 00 scored against the SemanticKITTI poses: report in build/kitti00/loop-report/.
kitti00-loops: $(KITTI00)/objects.stamp
	@$(MAKE) --no-print-directory build TARGETS=sgtllc_cli
	@mkdir -p $(KITTI00)/seq
	@cp data/kitti/00/poses_semantickitti.txt $(KITTI00)/seq/poses.txt
	@cp data/kitti/00/calib.txt $(KITTI00)/seq/calib.txt
	$(SGTLLC) eval $(KITTI00)/seq --nodes $(KITTI00)/objects --config $(KITTI00_CONFIG) --threads $(JOBS) \
	  --report $(KITTI00)/loop-report --force

# The whole KITTI 00 correction: loops + pose graph over the KISS-ICP odometry (drifting, no loop closure), then
# the trajectory errors against SemanticKITTI's poses (report in build/kitti00/report/), and the same back end
# with 5 % injected false loops (report in build/kitti00/report-false-loops/).
KITTI00_ODOMETRY = --odometry data/kitti/00/kissicp_00_kitti.txt --calib data/kitti/00/calib.txt
kitti00: $(KITTI00)/objects.stamp
	@$(MAKE) --no-print-directory build TARGETS=sgtllc_cli
	$(SGTLLC) run --nodes $(KITTI00)/objects --config $(KITTI00_CONFIG) --threads $(JOBS) $(KITTI00_ODOMETRY) \
	  --out $(KITTI00)/loops.csv --out-trajectory $(KITTI00)/corrected.txt --out-graph $(KITTI00)/graph.g2o \
	  --out-loops $(KITTI00)/loops.g2o --force
	$(SGTLLC) optimize $(KITTI00_ODOMETRY) --loops $(KITTI00)/loops.csv --config $(KITTI00_CONFIG) \
	  --ground-truth data/kitti/00/poses_semantickitti.txt --report $(KITTI00)/report --force
	$(SGTLLC) optimize $(KITTI00_ODOMETRY) --loops $(KITTI00)/loops.csv --config $(KITTI00_CONFIG) \
	  --ground-truth data/kitti/00/poses_semantickitti.txt --add-false-loops 0.05 --seed 7 \
	  --report $(KITTI00)/report-false-loops --force

bench: build
	$(BUILD)/bench/sgtllc_bench
	$(BUILD)/bench/sgtllc_bench_sim

# The libraries as a project without Ceres, Cairo, FAISS or Python builds them (the core, io, label, map), with the
# test suites that need nothing more: the back end, pipeline, tool, module and benchmarks are left out.
test-core:
	@$(MAKE) --no-print-directory build BUILD=build-core \
	  CMAKE_FLAGS="-DSGTLLC_WITH_BACKEND=OFF -DSGTLLC_WITH_FAISS=OFF $(CMAKE_FLAGS)"
	cd build-core && ctest --output-on-failure -j $(JOBS)

# ASan + UBSan over the whole suite (the tests run the instrumented command-line tool too).
test-sanitize:
	@$(MAKE) --no-print-directory build BUILD=build-asan DEPS_FLAGS=--dev \
	  CMAKE_FLAGS="$(CLANG_FLAGS) -DSGTLLC_SANITIZE=address,undefined $(CMAKE_FLAGS)"
	@scripts/sanitize/check.sh asan build-asan

# TSan over the threaded paths: the suites that run parallelFor at 2 threads (pair --list --threads 2 and 3 among
# them), and run/eval/simulate --threads 2.
TSAN_TESTS = test_parallel test_class_split test_node_extraction test_detector test_eval_protocol test_sim_output test_sim_cli test_cli \
  test_cli_pair_list
test-tsan:
	@$(MAKE) --no-print-directory build BUILD=build-tsan DEPS_FLAGS=--dev TARGETS="sgtllc_cli $(TSAN_TESTS)" \
	  CMAKE_FLAGS="$(CLANG_FLAGS) -DSGTLLC_SANITIZE=thread $(CMAKE_FLAGS)"
	@scripts/sanitize/check.sh tsan build-tsan $(TSAN_TESTS)

# Every libFuzzer harness for FUZZ_SECONDS each (FUZZ_HARNESSES: a subset, e.g. "pcd nodes").
fuzz:
	@$(MAKE) --no-print-directory build BUILD=build-fuzz DEPS_FLAGS=--dev TARGETS=sgtllc_fuzz \
	  CMAKE_FLAGS="$(CLANG_FLAGS) -DSGTLLC_FUZZ=ON -DSGTLLC_BUILD_APPS=OFF -DSGTLLC_BUILD_TESTS=OFF $(CMAKE_FLAGS)"
	@fuzz/run.sh build-fuzz $(FUZZ_SECONDS) $(FUZZ_HARNESSES)

# Before a release: every harness for 600 s, or for FUZZ_SECONDS given on the command line (CI keeps 30 s each).
FUZZ_LONG_SECONDS = $(if $(filter command line environment,$(origin FUZZ_SECONDS)),$(FUZZ_SECONDS),600)
fuzz-long:
	@$(MAKE) --no-print-directory fuzz FUZZ_SECONDS=$(FUZZ_LONG_SECONDS)

clean:
	rm -rf $(BUILD) $(BUILD).configure.log build-core build-asan build-tsan build-fuzz build-*.configure.log
