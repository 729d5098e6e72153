# The two commands of the README: `make demo` and `make test`. Both install missing Debian packages first.
# `make kitti00-loops` / `make kitti00`: loop detection / drift correction on all of KITTI 00 (object frames).
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?=
SGTLLC = $(BUILD)/apps/sgtllc/sgtllc
KITTI = data/kitti/00/velodyne
KITTI00 = $(BUILD)/kitti00
KITTI00_CONFIG = configs/kitti00-objects.yaml

.PHONY: all deps configure build demo test bench clean kitti00 kitti00-loops

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

# The 4,541 node files of KITTI 00 (data/README.md), unpacked once per change of the archive.
$(KITTI00)/objects.stamp: data/kitti/00/objects.tar.xz
	@mkdir -p $(KITTI00) && rm -rf $(KITTI00)/objects
	tar -xJf $< -C $(KITTI00)
	@touch $@

# Loop detection on KITTI 00 scored against the SemanticKITTI poses: report in build/kitti00/loop-report/.
kitti00-loops: build $(KITTI00)/objects.stamp
	@mkdir -p $(KITTI00)/seq
	@cp data/kitti/00/poses_semantickitti.txt $(KITTI00)/seq/poses.txt
	@cp data/kitti/00/calib.txt $(KITTI00)/seq/calib.txt
	$(SGTLLC) eval $(KITTI00)/seq --nodes $(KITTI00)/objects --config $(KITTI00_CONFIG) --threads $(JOBS) \
	  --report $(KITTI00)/loop-report --force

# The whole KITTI 00 correction: loops + pose graph over the KISS-ICP odometry (drifting, no loop closure).
kitti00: build $(KITTI00)/objects.stamp
	$(SGTLLC) run --nodes $(KITTI00)/objects --config $(KITTI00_CONFIG) --threads $(JOBS) \
	  --odometry data/kitti/00/kissicp_00_kitti.txt --calib data/kitti/00/calib.txt \
	  --out $(KITTI00)/loops.csv --out-trajectory $(KITTI00)/corrected.txt --force

bench: build
	$(BUILD)/bench/sgtllc_bench
	$(BUILD)/bench/sgtllc_bench_sim

clean:
	rm -rf $(BUILD) $(BUILD).configure.log
