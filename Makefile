# Two commands set everything up: `make run` and `make test`. Both install any missing
# Debian package (scripts/install-deps.sh), configure with CMake and build; only what
# changed is rebuilt (and ccache keeps rebuilds after `make clean` cheap).
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
RUN_OUT ?= out

.PHONY: all deps configure build run test bench clean

all: build

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > $(BUILD_DIR).configure.log 2>&1 \
	  || { cat $(BUILD_DIR).configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Until `grainmesh run` exists, `make run` runs the stages that do: a WC-Co microstructure
# (tessellate, mesh, export, and the case's Allrun: checkMesh and solidDisplacementFoam)
# and the thesis' 6-fibre cell (domain).
run: build
	./$(BUILD_DIR)/grainmesh tessellate data/examples/grains_wc_co.ini -o $(RUN_OUT)/grains_wc_co
	./$(BUILD_DIR)/grainmesh mesh $(RUN_OUT)/grains_wc_co/tessellation.json -o $(RUN_OUT)/grains_wc_co_mesh
	./$(BUILD_DIR)/grainmesh export $(RUN_OUT)/grains_wc_co_mesh/mesh.vtu -o $(RUN_OUT)/grains_wc_co_case --force
	$(RUN_OUT)/grains_wc_co_case/Allrun
	./$(BUILD_DIR)/grainmesh domain data/examples/fibres_6.ini -o $(RUN_OUT)/fibres_6
	@echo "make run: grains in $(RUN_OUT)/grains_wc_co/tessellation.{json,vtp,png}, their mesh in $(RUN_OUT)/grains_wc_co_mesh/mesh.{vtu,png}, the solved OpenFOAM case in $(RUN_OUT)/grains_wc_co_case (open case.foam in ParaView; logs log.*), the fibre mesh in $(RUN_OUT)/fibres_6/mesh.{vtu,png}; figures in each report.json"

test: build
	cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure

bench: build
	@cmake --build $(BUILD_DIR) --target bench

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log out
