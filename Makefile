# Two commands set everything up: `make run` and `make test`. Both install any missing
# Debian package (scripts/install-deps.sh), configure with CMake and build; only what
# changed is rebuilt (and ccache keeps rebuilds after `make clean` cheap).
BUILD_DIR ?= build
# cmake --build runs make again inside: without this every level says where it went.
MAKEFLAGS += --no-print-directory
JOBS ?= $(shell nproc)
RUN_OUT ?= out

.PHONY: all deps configure build san-configure san-build run test fuzz bench clean install

all: build

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR).configure.log 2>&1 \
	  || { cat $(BUILD_DIR).configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The sanitizer build beside it: clang, AddressSanitizer + UndefinedBehaviorSanitizer (any
# report fails the test), and the libFuzzer targets of tests/fuzz.
SAN_DIR ?= build-san
FUZZ_SECONDS ?= 600

san-configure: deps
	@CXX=clang++ CC=clang cmake -S . -B $(SAN_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DGRAINMESH_SANITIZE=ON > $(SAN_DIR).configure.log 2>&1 \
	  || { cat $(SAN_DIR).configure.log; exit 1; }

san-build: san-configure
	@cmake --build $(SAN_DIR) -j $(JOBS)

# The default pipeline: the program and the Python module built (the tests are make
# test's), the thesis' two-phase cell (data/default.ini, embedded in the binary)
# tessellated, meshed, exported, solved by OpenFOAM and homogenised: its answer last.
run: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target grainmesh grainmesh_python
	./$(BUILD_DIR)/grainmesh run -o $(RUN_OUT)/run --solve
	@echo "make run: pictures in $(RUN_OUT)/run/*.png, ParaView's results.vtu, the case in case/ (open case/case.foam), every number in report.json; from Python: PYTHONPATH=$(BUILD_DIR)/python (docs/python.md)"

# grainmesh and its cluster scripts into PREFIX/bin (grainmesh, grainmesh-slurm-sweep,
# grainmesh-slurm-cluster); DESTDIR stages them for a package.
PREFIX ?= /usr/local
DESTDIR ?=
install: build
	@DESTDIR="$(DESTDIR)" cmake --install $(BUILD_DIR) --prefix "$(PREFIX)"

# Every test twice: in the release build, then in the sanitizer build, which also runs each
# fuzz target for a fixed number of inputs (GRAINMESH_FUZZ_RUNS, the same on every machine).
test: build san-build
	cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure
	cd $(SAN_DIR) && ctest -j $(JOBS) --output-on-failure

# The long fuzz run: each target for FUZZ_SECONDS (600 s) from a new libFuzzer seed, its
# corpus kept in $(SAN_DIR)/fuzz-corpus; a failing input lands in $(SAN_DIR)/fuzz-artifacts.
fuzz: san-build
	@for t in config tessellation_json polygon_distance; do \
	  ./scripts/fuzz.sh $(SAN_DIR) $$t $(FUZZ_SECONDS) || exit 1; \
	done

# Benchmarks against Gmsh (installed here if missing) and CGAL; results in bench/results.json.
bench: build
	@./scripts/install-deps.sh --bench
	@cmake --build $(BUILD_DIR) --target bench

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log $(SAN_DIR) $(SAN_DIR).configure.log out
