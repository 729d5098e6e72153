# The two commands of the README: `make demo` and `make test`. Both install missing Debian packages first.
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?=
SGTLLC = $(BUILD)/apps/sgtllc/sgtllc
KITTI = data/kitti/00/velodyne

.PHONY: all deps configure build demo test bench clean

all: build

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > $(BUILD).configure.log 2>&1 \
	  || (cat $(BUILD).configure.log; exit 1)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	@echo "== KITTI 00: frame 4501 revisits frame 52 (2.96 m apart, ground truth) =="
	@$(SGTLLC) pair $(KITTI)/004501.bin $(KITTI)/000052.bin
	@echo
	@echo "== KITTI 00: frame 850 vs frame 88 (309 m apart: not a loop) =="
	@$(SGTLLC) pair $(KITTI)/000850.bin $(KITTI)/000088.bin

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD)/bench/sgtllc_bench
	$(BUILD)/bench/sgtllc_bench_sim

clean:
	rm -rf $(BUILD) $(BUILD).configure.log
