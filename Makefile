# SMA coupling sleeves (Pagano, Alart, Lebon 1998): FreeFEM scenes with a C++ load plugin.
#   make run  [SCENE=<scene>] [ARGS='-name value ...']   install, build, run a scene, draw its figures
#             [OUT=dir]                                  (SCENE may also name a variant of edp/variants)
#                                                        (ARGS=-help: list the scene's options only)
#   make run SCENE=sleeve-3d NP=2 [ARGS=...]             the same scene on NP MPI ranks, its solves through
#                                                        ffddm (edp/mpi/sleeve-3d.edp), into results/sleeve-3d-np2
#   make test                                            install, build, pass every test (ctest)
#   make figures                                         the paper's claims, each figure beside ours: docs/figures.md
#   make sweep SCENE=<scene> PARAM=g VALUES='250 500 1000' [PARAM2=interference VALUES2='2e-4 5e-4']
#              [ARGS=...] [JOBS=2] [OUT=dir]             one option (or two: their grid) swept: table and
#                                                        overlay figures (one panel per value of PARAM2)
#   make bench                                           speed against error: docs/benchmarks.md
#   make reference                                       the force curve's accuracy reference: docs/reference.md
#   make paper-scale                                     fit a and the open choices to the paper's statements: docs/paper-scale.md
#   make ensemble [NP=2] [SEEDS=8] [OUT=dir] [ARGS=...]  Monte Carlo over seeds of sleeve-random-threshold on MPI
#   make docs                                            regenerate docs/parameter-reference.md (scenes' -help)
#                                                        and docs/python-api.md (the sma package's docstrings)
#   make lab                                             the students' notebook (docs/tutorial/sleeve-lab.ipynb) in
#                                                        Jupyter, on this checkout's package (installs jupyter-notebook)
#   make python                                          only when asked: install the sma package (python/sma) for
#                                                        the user, editable and offline: `import sma` from anywhere
#   make help                                            this list, the scenes and variants, and where to start
#   make clean                                           remove what the build made (build/, plugin/build/, the
#                                                        meshes); results/ is kept
SHELL := /bin/bash
# A user's CDPATH sends a relative `cd` to a folder it names (tools/ff says more): never the recipes'.
unexport CDPATH
.DEFAULT_GOAL := run

SCENES := $(sort $(basename $(notdir $(wildcard edp/scenes/*.edp))))
# The variants of docs/variants.md run the same way (make run SCENE=<variant>), into results/variants/.
VARIANTS := $(sort $(basename $(notdir $(wildcard edp/variants/*.edp))))
# Every goal on the command line must be a target: a scene given as a goal (make run sleeve-radial)
# ran the default scene, replacing its results, and only then failed. Refused before anything runs.
# (File targets, with a /, pass: make meshes/sleeve-nr27.msh.)
TARGETS := run test figures bench reference paper-scale ensemble docs deps plugin plugin-files meshes clean \
           check-scene sweep python lab help
STRAY_GOALS := $(filter-out $(TARGETS),$(foreach g,$(MAKECMDGOALS),$(if $(findstring /,$(g)),,$(g))))
ifneq ($(STRAY_GOALS),)
$(shell g='$(firstword $(STRAY_GOALS))'; if [[ " $(SCENES) $(VARIANTS) " == *" $$g "* ]]; then \
  echo "error: '$$g' is a scene, not a make target: make run SCENE=$$g (make help lists the targets)" >&2; \
  else echo "error: unknown make target '$$g' (make help lists the targets, the scenes and the variants)" >&2; fi)
$(error stopped before anything ran)
endif
SCENE ?= sleeve-circular
ARGS ?=
PYTHON := /usr/bin/python3
FF := tools/ff

PLUGIN := plugin/build/sma.so
# The plugin's glue units (plugin/glue/*.cpp), each compiled on its own, in parallel (only
# step.cpp includes the step solver, the slow one), and again only when it or a header it
# includes changed (the compiler's dependency lists, plugin/build/<unit>.d). Without debug
# information (ff-c++ asks for -g: 86 MB of object, half the compile time); PLUGIN_DEBUG=1 keeps it.
# (step, the longest, first: make -j starts the units in this order.)
PLUGIN_UNITS := step $(filter-out step,$(sort $(notdir $(basename $(wildcard plugin/glue/*.cpp)))))
PLUGIN_OBJECTS := $(PLUGIN_UNITS:%=plugin/build/%.o)
PLUGIN_CXX := ../../tools/cxx17$(if $(filter-out 0,$(PLUGIN_DEBUG)), --debug)
PLUGIN_FLAGS := plugin/build/compile-flags
CORES := $(shell nproc 2>/dev/null || echo 2)
# clock() without a system call, preloaded by tools/ff (plugin/fastclock.c says why).
FASTCLOCK := plugin/build/fastclock.so
# The results folder's claim for the Python tools (a sweep's folder): plugin/results_tool.cpp.
RESULTS_TOOL := plugin/build/sma-results
# Out of memory ends a run with one error line (exit 12), preloaded by tools/ff (plugin/oomguard.c says why).
OOMGUARD := plugin/build/oomguard.so
# ffddm's scripts load "MUMPS_mpi", which Debian's FreeFEM lacks: a stand-in, UMFPACK on one rank for GenEO's
# coarse problem (plugin/ffddm/MUMPS_mpi.cpp says why).
FFDDM_STUB := plugin/build/ffddm/MUMPS_mpi.so

# gmsh meshes (MSH 2.2: FreeFEM's gmshload does not read MSH 4): meshes/<geo>-<level>.msh is
# made from meshes/<geo>.geo with the gmsh options <geo>_opt_<level> (the .geo files say why).
BEAM_MESHES := meshes/beam-coarse.msh meshes/beam-medium.msh meshes/beam-fine.msh
RING_MESHES := meshes/ring-coarse.msh meshes/ring-l1.msh meshes/ring-l2.msh meshes/ring-l3.msh meshes/ring-l4.msh
SLEEVE_MESHES := meshes/sleeve-coarse.msh meshes/sleeve-quarter.msh meshes/sleeve-aniso.msh \
                 meshes/sleeve-half-coarse.msh meshes/sleeve-half.msh meshes/sleeve-nr9.msh meshes/sleeve-nr12.msh \
                 meshes/sleeve-nr36.msh meshes/sleeve-aniso36.msh meshes/sleeve-aniso108.msh
# Quarter rings with nearly degenerate triangles (docs/stability.md, case 6).
SLIVER_MESHES := meshes/sliver-thin.msh meshes/sliver-degenerate.msh
# Pipe mesh files for the 2D scenes' -pipemesh (meshes/pipe.geo; by default the scenes make a pipe
# mesh that follows the ring's): a solid shaft and a wall, the pipe's radius from
# meshes/sleeve-geometry.txt; the scenes stretch them to -pipeRi .. -pipeA.
PIPE_MESHES := meshes/pipe-solid.msh meshes/pipe-wall.msh
MESHES := $(BEAM_MESHES) $(RING_MESHES) $(SLEEVE_MESHES) $(SLIVER_MESHES) $(PIPE_MESHES)
beam_opt_coarse := -setnumber lc 0.0021
beam_opt_medium := -setnumber lc 0.00125
beam_opt_fine := -setnumber lc 0.0007
ring_opt_coarse := -setnumber lc 0.002
ring_opt_l1 := -setnumber nr 4
ring_opt_l2 := -setnumber nr 8
ring_opt_l3 := -setnumber nr 16
ring_opt_l4 := -setnumber nr 32
# The sleeve's ring: inner radius 55 um below the pipe's 5.05 cm (docs/parameters.md, sleeve), read
# from meshes/sleeve-geometry.txt, the one place of the sleeve's dimensions (the scripts read it too).
SLEEVE_GEOMETRY := meshes/sleeve-geometry.txt
SLEEVE_RING := -setnumber Ri $(shell awk '$$1 == "Ri" {print $$2}' $(SLEEVE_GEOMETRY)) \
               -setnumber Hr $(shell awk '$$1 == "Hr" {print $$2}' $(SLEEVE_GEOMETRY))
sleeve_opt_coarse := $(SLEEVE_RING) -setnumber nr 6
sleeve_opt_quarter := $(SLEEVE_RING) -setnumber nr 18
# sleeve-circular's mesh: the same 18 layers through the thickness, 18 segments (5 degrees) along
# the arc: at the reduced scale the circular fit's error is the layers'; at the paper's the arc
# carries about as much (docs/benchmarks/mesh-refinement.md).
sleeve_opt_aniso := $(SLEEVE_RING) -setnumber nr 18 -setnumber nt 18
sleeve_opt_half-coarse := $(sleeve_opt_coarse) -setnumber half 1
sleeve_opt_half := $(sleeve_opt_quarter) -setnumber half 1
# The refinement levels of the quarter ring (nr 6 and 18 are sleeve-coarse, sleeve-quarter; 9 and
# 12 are used by tests/sleeve_convergence_test.py, 36 by tests/step_solver_test.py (1 s steps: 1440
# points transform at once) and the benchmarks, 27 by the benchmarks only; -aniso36 is
# sleeve-aniso with twice its layers, for tests/moving_layers_test.py). nr 72, 108 and 140 (26k, 59k and 99k nodes) extend the
# scaling series of the benchmarks (tools/bench/scaling.py: 18, 36, 72, 108, 140 layers); made by
# make bench only.
BENCH_MESHES := meshes/sleeve-nr27.msh \
                meshes/sleeve-nr72.msh meshes/sleeve-nr108.msh meshes/sleeve-nr140.msh
# Meshes written in millimetres, with a $$MeshUnit section saying so (docs/parameters.md, Mesh
# units): in metres the triangles of nr 108 and 140 fall below gmshload's floor of 1e-8 (area, in
# the file's units; nr 72 is just above it), and edp/lib/mesh.idp LoadMesh scales them back.
MILLIMETRE_MESHES := meshes/sleeve-nr72.msh meshes/sleeve-nr108.msh meshes/sleeve-nr140.msh
sleeve_opt_nr9 := $(SLEEVE_RING) -setnumber nr 9
sleeve_opt_nr12 := $(SLEEVE_RING) -setnumber nr 12
sleeve_opt_nr27 := $(SLEEVE_RING) -setnumber nr 27
sleeve_opt_nr36 := $(SLEEVE_RING) -setnumber nr 36
sleeve_opt_aniso36 := $(SLEEVE_RING) -setnumber nr 36 -setnumber nt 18
# 108 layers and sleeve-aniso's 18 arc segments: with the ring's true heat measure and -tol 3e-4,
# sleeve-circular within 0.1 % of the reference over the reversion window in about 2.4 s
# (docs/reference-paper.md; the arc's part of the error is gone, the layers' is first order).
sleeve_opt_aniso108 := $(SLEEVE_RING) -setnumber nr 108 -setnumber nt 18
sleeve_opt_nr72 := $(SLEEVE_RING) -setnumber nr 72
sleeve_opt_nr108 := $(SLEEVE_RING) -setnumber nr 108
sleeve_opt_nr140 := $(SLEEVE_RING) -setnumber nr 140
# Triangles of about 2 mm in the solid shaft (whose displacement, linear in r, P1 represents
# exactly) and 0.5 mm in the 5.5 mm wall (docs/parameters.md: its error then below the ring's).
PIPE_RADIUS := -setnumber R $(shell awk '$$1 == "pipe" {print $$2}' $(SLEEVE_GEOMETRY))
pipe_opt_solid := $(PIPE_RADIUS) -setnumber lc 0.002
pipe_opt_wall := $(PIPE_RADIUS) -setnumber Ri 0.045 -setnumber lc 0.0005
sliver_opt_thin := $(SLEEVE_RING) -setnumber eps 1.3e-5
sliver_opt_degenerate := $(SLEEVE_RING) -setnumber eps 1e-8

.PHONY: run test figures bench reference paper-scale ensemble docs deps plugin plugin-files meshes clean check-scene sweep python lab help
# The scenes behind the paper's figures (docs/figures.md), run at their defaults by make figures (the
# sleeve scenes at the paper's 1500 fixed increments, -tol 0).
FIGURE_SCENES := beam sleeve-circular sleeve-circular-single sleeve-circular-gvar sleeve-offset \
                 sleeve-elliptic sleeve-elliptic-friction sleeve-random-threshold

deps:
	@tools/install-deps.sh

# The sma package (python/sma) for /usr/bin/python3, editable (the checkout's own files: an edit is
# seen at once, and the package finds this checkout's scenes), with Debian's pip and setuptools,
# offline; --break-system-packages because Debian marks its Python externally managed (PEP 668):
# a --user install with no dependencies touches only ~/.local (docs/parameters.md, "The Python
# package"). Skipped when `import sma` from another folder already gives this checkout. No other
# target runs it: make never writes the user's site-packages unless asked (the tools, the tests
# and `make lab` put this checkout's python/ first on their path; two checkouts took the package
# from each other at every make).
python: deps
	@here=$$(pwd -P); cd / && if [ "$$($(PYTHON) -c 'import sma; print(sma.ROOT)' 2>/dev/null)" != "$$here" ]; then \
	  cd "$$here" && PIP_ROOT_USER_ACTION=ignore $(PYTHON) -m pip install --user --break-system-packages --no-index \
	    --no-build-isolation --no-deps --disable-pip-version-check -q -e python/ > python/install.log 2>&1 \
	  || { cat python/install.log; echo "error: installing the sma package (python/) failed (python/install.log)" >&2; exit 1; }; \
	  rm -f python/install.log; echo "installed the sma package for $$(id -un): import sma runs $$here"; fi

# The plugin's files are made by a make of their own, its jobs as many as the cores unless this
# make was given -j: `make run` builds the plugin's units in parallel.
plugin: deps
	@$(MAKE) --no-print-directory $(if $(findstring -j,$(MAKEFLAGS)),,-j$(CORES)) plugin-files
plugin-files: $(PLUGIN) $(FASTCLOCK) $(RESULTS_TOOL) $(OOMGUARD) $(FFDDM_STUB)
	@:
$(FFDDM_STUB): plugin/ffddm/MUMPS_mpi.cpp
	@mkdir -p plugin/build/ffddm
	@cd plugin/build/ffddm && ff-c++ ../../ffddm/MUMPS_mpi.cpp -DHAVE_LIBUMFPACK -DHAVE_SUITESPARSE_UMFPACK_H -lumfpack > build.log 2>&1 \
	  || { cat build.log; echo "error: building $@ failed (plugin/build/ffddm/build.log)" >&2; exit 1; }
$(RESULTS_TOOL): plugin/results_tool.cpp plugin/core/files.hpp
	@mkdir -p plugin/build
	@g++ -std=c++17 -O2 -Wall -Werror plugin/results_tool.cpp -o $@
$(FASTCLOCK): plugin/fastclock.c
	@mkdir -p plugin/build
	@cc -O2 -shared -fPIC -Wall -Werror plugin/fastclock.c -o $@
$(OOMGUARD): plugin/oomguard.c
	@mkdir -p plugin/build
	@cc -O2 -shared -fPIC -Wall -Werror plugin/oomguard.c -o $@
# The compiler command the objects were made with, rewritten (as this Makefile is read, by the
# make that builds them) only when it changes: a change (PLUGIN_DEBUG) remakes them all.
ifneq ($(filter plugin-files,$(MAKECMDGOALS)),)
ifneq ($(shell cat $(PLUGIN_FLAGS) 2>/dev/null),$(PLUGIN_CXX))
$(shell mkdir -p plugin/build && echo '$(PLUGIN_CXX)' > $(PLUGIN_FLAGS))
endif
endif
# A unit's dependency list names the files as the compiler saw them from plugin/build (../core/x):
# rewritten from the checkout's root, where this Makefile reads it (only a path that starts with
# ../: Eigen's own names hold /../ inside).
plugin/build/%.o: plugin/glue/%.cpp $(PLUGIN_FLAGS)
	@echo "compiling plugin/glue/$*.cpp$(if $(filter step,$*), (the step solver: the longest unit, about 45 s),)"
	@cd plugin/build && ff-c++ "CXX=$(PLUGIN_CXX)" -c ../glue/$*.cpp -I/usr/include/eigen3 -I/usr/include/suitesparse -I.. \
	  > $*.log 2>&1 || { rm -f $*.o $*.d; cat $*.log; echo "error: compiling plugin/glue/$*.cpp failed (plugin/build/$*.log)" >&2; exit 1; }
	@sed -i -e 's#\(^\| \)\.\./#\1plugin/#g' -e 's#^$*\.o:#plugin/build/$*.o:#' plugin/build/$*.d
-include $(wildcard plugin/build/*.d)
$(PLUGIN): $(PLUGIN_OBJECTS)
	@cd plugin/build && ff-c++ "CXX=$(PLUGIN_CXX)" $(notdir $(PLUGIN_OBJECTS)) -o sma -lcholmod > link.log 2>&1 \
	  || { cat link.log; echo "error: linking the plugin failed (plugin/build/link.log)" >&2; exit 1; }
	@test -f $(PLUGIN) || { cat plugin/build/link.log; echo "error: ff-c++ made no $(PLUGIN)" >&2; exit 1; }
	@echo "built $(PLUGIN)"

meshes: deps $(MESHES)
# A mesh of MILLIMETRE_MESHES: gmsh scales the coordinates by 1000 as it writes them, and the
# $$MeshUnit section (0.001 m per unit) goes in after $$EndMeshFormat, all in a .part file renamed
# when complete (a mesh in mm without its section would be read as metres).
define gmsh_mesh
	@$(if $(filter $@,$(MILLIMETRE_MESHES)),\
	  gmsh -2 -format msh22 $($(1)_opt_$*) -setnumber Mesh.ScalingFactor 1000 $< -o $@.part > $@.log 2>&1 \
	  && sed -i '/^\$$EndMeshFormat/a $$MeshUnit\n0.001\n$$EndMeshUnit' $@.part && mv $@.part $@,\
	  gmsh -2 -format msh22 $($(1)_opt_$*) $< -o $@ > $@.log 2>&1) \
	  || { cat $@.log; echo "error: gmsh failed on $<" >&2; exit 1; }
	@rm -f $@.log
endef
meshes/beam-%.msh: meshes/beam.geo
	$(call gmsh_mesh,beam)
meshes/ring-%.msh: meshes/ring.geo
	$(call gmsh_mesh,ring)
meshes/sleeve-%.msh: meshes/ring.geo $(SLEEVE_GEOMETRY)
	$(call gmsh_mesh,sleeve)
meshes/sliver-%.msh: meshes/sliver.geo $(SLEEVE_GEOMETRY)
	$(call gmsh_mesh,sliver)
meshes/pipe-%.msh: meshes/pipe.geo $(SLEEVE_GEOMETRY)
	$(call gmsh_mesh,pipe)

# SCENE reaches the shell through the environment, never pasted into the recipe, so that quotes
# or backquotes in it are only characters (docs/errors.md).
check-scene: export SCENE_NAME := $(value SCENE)
check-scene:
	@if [[ ! "$$SCENE_NAME" =~ ^[A-Za-z0-9_-]+$$ ]]; then \
	  echo "error: SCENE='$$SCENE_NAME' is not a scene name (letters, digits, - and _ only)" >&2; \
	  echo "scenes: $(SCENES)" >&2; exit 2; fi
	@if [[ " $(SCENES) $(VARIANTS) " != *" $$SCENE_NAME "* ]]; then \
	  echo "error: unknown scene '$$SCENE_NAME'" >&2; echo "scenes: $(SCENES)" >&2; \
	  echo "variants: $(VARIANTS)" >&2; exit 2; fi

IS_VARIANT = $(filter $(SCENE),$(VARIANTS))
RUN_SCRIPT = $(if $(IS_VARIANT),edp/variants,edp/scenes)/$(SCENE).edp
RUN_RESULTS = $(if $(IS_VARIANT),results/variants,results)/$(SCENE)
# The figures of the scene: its own tools/plot/plot_<scene>.py, else the sleeve's or the variants' (the
# output folder is appended).
RUN_PLOT = $(if $(wildcard tools/plot/plot_$(SCENE).py),$(PYTHON) tools/plot/plot_$(SCENE).py,$(if \
           $(filter sleeve-%,$(SCENE)),$(PYTHON) tools/plot/plot_sleeve.py,$(if $(IS_VARIANT),$(PYTHON) \
           tools/plot/plot_variants.py --only $(SCENE) results/variants)))
# ARGS reaches tools/run_scene.py through the environment, never pasted into the recipe: a `;` or
# a `$(...)` in it is a character, not a command (docs/errors.md). run_scene.py draws the figures
# from the folder the run wrote (a -out among ARGS included).
# NP on make's command line (not NP in the environment, nor make ensemble's default) runs the scene's
# distributed version, edp/mpi/$(SCENE).edp, on NP ranks (tools/ff-mpi); NP reaches run_scene.py,
# which checks it is a whole number, through the environment.
# OUT=dir (given on the command line or in the environment, as make sweep's) names the results
# folder, as ARGS='-out dir' does; make run ignored it before, writing elsewhere without a word.
run: export RUN_ARGS := $(value ARGS)
run: export RUN_OUT := $(value OUT)
run: export RUN_NP := $(if $(filter command line,$(origin NP)),$(value NP))
RUN_OUT_OPTION = $(if $(filter command line environment environment override override,$(origin OUT)),--env-out RUN_OUT)
run: check-scene plugin meshes
	@if [ -z "$$RUN_NP" ]; then \
	  $(PYTHON) tools/run_scene.py --env-args RUN_ARGS $(RUN_OUT_OPTION) $(RUN_SCRIPT) $(RUN_RESULTS) $(RUN_PLOT); \
	elif [ ! -f edp/mpi/$(SCENE).edp ]; then \
	  echo "error: SCENE=$(SCENE) has no distributed run (NP=...): the scenes of edp/mpi/ have one:" \
	    "$(notdir $(basename $(wildcard edp/mpi/*.edp)))" >&2; exit 2; \
	else \
	  $(PYTHON) tools/run_scene.py --env-args RUN_ARGS $(RUN_OUT_OPTION) --ranks "$$RUN_NP" edp/mpi/$(SCENE).edp \
	    "$(RUN_RESULTS)-np$$(printf '%s' "$$RUN_NP" | tr -c '0-9' _)" $(RUN_PLOT); \
	fi

# A checkout copied or moved elsewhere keeps a build/CMakeCache.txt naming the old folder, which
# cmake refuses: such a build/ is another checkout's and is rebuilt from scratch.
# (the plugin and the unit tests one after the other: both at once, four 2 GB compiles on 2 cores,
# took 240 s of wall and 455 s of processor time from a fresh clone, against 79 + 108 = 187 s and
# 355 s, measured on this machine idle)
test: plugin meshes
	@if [ -f build/CMakeCache.txt ] && ! grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$$(pwd -P)" build/CMakeCache.txt; then \
	  echo "build/ was configured for another folder ($$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' build/CMakeCache.txt)): rebuilding it"; \
	  rm -rf build; fi
	@mkdir -p build && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build/cmake.log 2>&1 || \
	  { mkdir -p build; cmake -S . -B build -DCMAKE_BUILD_TYPE=Release; }
	@echo "make test: building the C++ unit tests (GoogleTest: about 1.5 min the first time on 2 cores, then only what changed)"
	@cmake --build build -j$(CORES)
	@echo "make test: running every test with ctest on $(CORES) cores (about 7 min on 2; each line is one test as it ends)"
	@cd build && ctest --output-on-failure -j$(CORES)

# A parameter sweep (tools/sweep.py): each value of PARAM run in parallel (JOBS, at most the cores),
# then results/sweeps/<scene>-<param>/table.csv and overlay figures. Nothing the user types is
# pasted into the recipe: every make variable reaches the shell through the environment. ARGS is
# read by sweep.py itself (--env-args: split into words like a shell's, never run by one, so
# ARGS='-steps 30; touch x' is the option -steps '30;' and two stray words, an error, and nothing
# runs); VALUES too (--env-values: split at white space, each word a value, never a flag: VALUES='--out=x 500'
# is refused as a value, not taken as --out).
# OUT counts only when given (command line or environment): make ensemble's default OUT is not a
# sweep's folder, wherever its line stands in this file.
SWEEP_OUT_DEFAULT = results/sweeps/$(SCENE)-$(PARAM)$(if $(PARAM2),-$(PARAM2))
sweep: export SWEEP_SCENE := $(value SCENE)
sweep: export SWEEP_PARAM := $(value PARAM)
sweep: export SWEEP_VALUES := $(value VALUES)
sweep: export SWEEP_PARAM2 := $(value PARAM2)
sweep: export SWEEP_VALUES2 := $(value VALUES2)
sweep: export SWEEP_ARGS := $(value ARGS)
sweep: export SWEEP_JOBS := $(or $(value JOBS),2)
sweep: export SWEEP_DIR := $(if $(filter command line environment environment override override,$(origin OUT)),$(value OUT),$(SWEEP_OUT_DEFAULT))
sweep: check-scene plugin meshes
	@set -f; if [ -z "$$SWEEP_PARAM" ] || [ -z "$$SWEEP_VALUES" ]; then \
	  echo "error: make sweep needs PARAM=<option without its dash> and VALUES='<v1> <v2> ...'" >&2; exit 2; fi; \
	  second=(); if [ -n "$$SWEEP_PARAM2" ] || [ -n "$$SWEEP_VALUES2" ]; then \
	    second=(--param2 "$$SWEEP_PARAM2" --env-values2 SWEEP_VALUES2); fi; \
	  $(PYTHON) tools/sweep.py "$$SWEEP_SCENE" "$$SWEEP_PARAM" --env-values SWEEP_VALUES --jobs "$$SWEEP_JOBS" \
	    --out "$$SWEEP_DIR" --env-args SWEEP_ARGS "$${second[@]}"

# Speed against error, all measured in one run: docs/benchmarks.md, results/bench/summary.json.
bench: plugin meshes $(BENCH_MESHES)
	@$(PYTHON) tools/bench/bench.py

# The Richardson extrapolation of the radial force curve, its assumptions tested, the on/off scheme
# and the defaults measured against it (tools/bench/reference_curve.py; about 40 s).
reference: plugin meshes
	@$(PYTHON) tools/bench/reference_curve.py

# The paper's own scale: a, the faces' heat exchange and the random spread fitted to the paper's
# statements (tools/docs/paper_scale_fit.py, about 12 min; runs in /tmp/paper-scale-fit).
paper-scale: plugin meshes
	@$(PYTHON) tools/docs/paper_scale_fit.py

# Monte Carlo over the seeds of sleeve-random-threshold, seeds round-robin over NP MPI ranks
# (docs/ensembles.md). OpenMPI refuses root without the two ALLOW variables; an idle rank yields
# the core to the others' children instead of busy-polling. The ranks are started by mpiexec
# itself, never through Debian's ff-mpirun, which joins its arguments into a string for `eval`
# (a `;` in ARGS or OUT ran as a command); NP and SEEDS must be whole numbers >= 1.
NP ?= 2
SEEDS ?= 8
OUT ?= results/sleeve-random-ensemble
# OUT and ARGS reach tools/run_scene.py through the environment (see run), NP and SEEDS as its
# arguments (each one word, never pasted into a shell), which it checks are whole numbers.
ensemble: export RUN_ARGS := $(value ARGS)
ensemble: export RUN_OUT := $(value OUT)
ensemble: export ENSEMBLE_NP := $(value NP)
ensemble: export ENSEMBLE_SEEDS := $(value SEEDS)
ensemble: plugin meshes
	@OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 \
	  FF_INCLUDEPATH="$$(pwd -P)/edp/lib;$$(pwd -P)/edp/model;$$(pwd -P)/edp/solvers;$$(pwd -P)/edp/problems;/usr/include/freefem++/idp;./" \
	  FF_LOADPATH="$$(pwd -P)/plugin/build;/usr/lib/freefem++;./" \
	  $(PYTHON) tools/run_scene.py --env-args RUN_ARGS --env-out RUN_OUT --mpi "$$ENSEMBLE_NP" --seeds "$$ENSEMBLE_SEEDS" \
	  edp/ensemble/sleeve-random-ensemble.edp results/sleeve-random-ensemble \
	  $(PYTHON) tools/plot/plot_ensemble.py

# The lab notebook in Jupyter's browser front end (Debian's jupyter-notebook, installed here when
# missing: make deps does not, the tests execute the notebook headless), with this checkout's
# package first on the kernel's path. Root needs --allow-root.
lab: plugin meshes
	@tools/install-deps.sh jupyter-notebook
	@PYTHONPATH="$$(pwd -P)/python$${PYTHONPATH:+:$$PYTHONPATH}" jupyter notebook \
	  $$([ "$$(id -u)" = 0 ] && echo --allow-root) docs/tutorial/sleeve-lab.ipynb

help:
	@echo "Where to start:"
	@echo "  1. make run                  the default scene (sleeve-circular, the paper's Fig. 12): results/sleeve-circular/,"
	@echo "                               its figures *.png and summary.json (the first run builds the plugin: about 1 min on 2 cores)"
	@echo "  2. make run SCENE=sleeve-radial ARGS='-help'   a scene's options; then ARGS='-g 1000 -out results/g1000'"
	@echo "  3. make lab                  the students' notebook in Jupyter (README.md, docs/tutorial/)"
	@echo "Targets:"
	@sed -n '2,/^SHELL/ s/^#//p' Makefile | sed '/^ *make help/d'
	@echo "Scenes (make run SCENE=...): $(SCENES)" | fold -s -w 100
	@echo "Variants (make run SCENE=..., docs/variants.md): $(VARIANTS)" | fold -s -w 100

# (the sleeve scenes at the paper's 1500 fixed increments, -tol 0: the claims are judged on them)
figures: test
	@for scene in $(FIGURE_SCENES); do \
	  case $$scene in sleeve-*) args="-quiet 1 -tol 0 -out results/$$scene" ;; *) args='-quiet 1' ;; esac; \
	  $(MAKE) --no-print-directory run SCENE=$$scene ARGS="$$args" || exit 1; done
	@$(PYTHON) tools/docs/claims.py --run
	@$(PYTHON) tools/docs/figures.py

# Every option of every scene, variant, benchmark and the ensemble, as each prints them with
# -help tsv (tools/docs/param_reference.py says how; about 1 s); the sma package's API page from its
# docstrings (tools/docs/python_api.py).
docs: plugin
	@$(PYTHON) tools/docs/param_reference.py
	@$(PYTHON) tools/docs/python_api.py

# What the build made, never results/: the runs' results are data (an hour's sleeve-3d, an
# ensemble, a user's notes beside them), and `make clean` is typed to rebuild (it removed them all).
clean:
	rm -rf build plugin/build meshes/*.msh
	@[ ! -d results ] || echo "results/ kept: your runs' results (remove what you no longer need yourself)"
