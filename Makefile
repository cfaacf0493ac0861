# Kovtunenko (1994), a clamped plate over a rigid obstacle: build, test, reproduce.
# `make all` and `make test` install what is missing (make deps) and build first.
BUILD ?= build
JOBS  ?= $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)
DRIVERS := $(BUILD)/table $(BUILD)/fig1 $(BUILD)/fig2 $(BUILD)/contraction $(BUILD)/hard_cases $(BUILD)/bench $(BUILD)/peer_snesvi \
           $(BUILD)/micro_bench $(BUILD)/continuum $(BUILD)/time_to_accuracy $(BUILD)/prose_numbers $(BUILD)/compare_tables $(BUILD)/rim_series \
           $(BUILD)/liftoff $(BUILD)/kink_study $(BUILD)/render_report
TESTS := $(BUILD)/unit_tests $(BUILD)/fine_tests $(BUILD)/program_tests $(BUILD)/freefem_tests $(BUILD)/document_tests
BINS  := $(BUILD)/plate $(BUILD)/crosscheck $(BUILD)/crosscheck_penalty $(TESTS) $(DRIVERS)
PAPER_NUMBERS := reference/paper_numbers.csv

TABLE_PAPER := results/table.md results/table.csv
TABLE_FINE  := results/table_fine.md results/table_fine.csv
TABLES    := $(TABLE_PAPER) $(TABLE_FINE)
FIG1_DATA := results/fig1_points.csv results/fig1_surface.dat results/fig1_contact.dat
FIG2_DATA := results/fig2.csv results/fig2_mesh.csv results/fig2_fit.md results/fig2_mesh.md
FIGURES   := results/fig1.svg results/fig1.png results/fig2.svg results/fig2.png results/contraction.svg results/contraction.png \
             results/linear_history.svg results/linear_history.png
CONTRACTION := results/contraction.md results/contraction.csv results/linear_history.csv
RESULTS   := $(TABLES) $(CONTRACTION) $(FIG1_DATA) $(FIG2_DATA) $(FIGURES)
CROSSCHECK := results/crosscheck.md results/crosscheck.csv results/crosscheck_agreement.csv results/crosscheck_rim.csv \
              results/crosscheck_timings.csv
RIM_FIGURE := results/rim.svg results/rim.png
CROSSCHECK_PENALTY := results/crosscheck_penalty.md results/crosscheck_penalty_table.csv results/crosscheck_penalty_eps.csv results/crosscheck_penalty_limits.csv \
                      results/crosscheck_penalty_fig2.csv
PENALTY_FIGURE := results/crosscheck_penalty_fig2.svg results/crosscheck_penalty_fig2.png
# The paper's table as a plot: the published counts, ours and FreeFEM's, gathered by crosscheck_penalty.
TABLE_FIGURE := results/table_iterations.svg results/table_iterations.png
HARD_CASES := results/hard_cases.md results/hard_cases_input.md results/hard_cases_point.csv results/hard_cases_timings.csv
NUMBERS   := results/numbers.csv results/numbers_machine.csv
CONTINUUM_DATA := results/continuum.md results/continuum.csv results/continuum_error.csv results/continuum_q.csv \
                  results/continuum_answer.md results/continuum_limits.csv results/continuum_timings.csv
RIM_SERIES := results/rim_series.md results/rim_series.csv results/rim_answer.csv results/uniform_load.csv
LIFTOFF   := results/liftoff.md results/liftoff.csv results/liftoff_timings.csv
KINK_DATA := results/kink.md results/kink.csv results/kink_stability.csv results/kink_polygon.csv
OWN_SCENES := results/own_scenes.md
KINK      := $(KINK_DATA) results/kink.svg results/kink.png
CONTINUUM := $(CONTINUUM_DATA) results/continuum.svg results/continuum.png results/continuum_q.svg results/continuum_q.png
BENCH     := results/speed_vs_error.csv results/speed_vs_error.md
BENCH_LARGE := results/large/speed_vs_error.csv results/large/speed_vs_error.md
TTA       := results/time_to_accuracy.csv results/time_to_accuracy.md
BENCH_ALL := $(BENCH) results/speed_vs_error.svg results/speed_vs_error.png results/micro_benchmarks.md \
             $(TTA) results/time_to_accuracy.svg results/time_to_accuracy.png
PAPER_INPUTS := paper/paper.md paper/style.css paper/print.html $(wildcard paper/filters/*.lua) reports/words.md $(BUILD)/render_report $(wildcard src/*.cpp src/*.hpp src/programs/*.cpp src/programs/support/*.cpp src/programs/support/*.hpp) \
                $(RESULTS) $(RIM_SERIES) $(CONTINUUM) $(LIFTOFF) $(KINK) $(OWN_SCENES) $(CROSSCHECK) $(RIM_FIGURE) $(CROSSCHECK_PENALTY) $(PENALTY_FIGURE) $(TABLE_FIGURE) $(HARD_CASES) $(BENCH_ALL) $(BENCH_LARGE) $(NUMBERS)
# The packages whose versions the document's reference list gives.
VERSIONED := libeigen3-dev libsuitesparse-dev libopenblas0-pthread libmuparser-dev libcli11-dev freefem++ gmsh \
             libpetsc-real-dev libmumps-dev pandoc gnuplot-nox g++ cmake libgtest-dev libbenchmark-dev

# Every program make runs gets one thread and an allocator that keeps what it frees. On this virtual
# machine the first write to a page of a process's memory costs about 5 us of system time
# (plate -n 512 --sampling nodes --symmetry none: 4.6 s for 890 000 faults, 1.4 s a GiB), a page
# written before in the same process nothing; it looks as if the host takes back what the guest has
# freed for a second or so. So glibc keeps every block it frees in its heap for the next one
# (mmap_max=0, trim_threshold) instead of unmapping it (in the main arena, where our solves
# allocate; a thread's own arena still unmaps blocks beyond its 64 MiB heaps). Huge pages, which an
# earlier round asked for (hugetlb=1), come back slower still once freed a few seconds
# (scripts/first_write.sh: 0.7 GB/s on first write, against 2.8 with small pages and 35 to 40 GB/s
# on a second write). System time with huge pages and with these: 5.0 to 8.3 s and 4.6 to 5.3 s for
# that plate run, 5.3 s and 1.0 s for `continuum` run alone. CHOLMOD asks OpenMP for 4 threads
# whatever the machine has, and OpenBLAS starts one per core: on our blocks they mostly wait on each
# other in the kernel. Set any of them on the command line to override; `make check-results`
# compares the tables made with them.
export OMP_THREAD_LIMIT ?= 1
export OPENBLAS_NUM_THREADS ?= 1
export GLIBC_TUNABLES ?= glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295

# What each step makes and about how long it takes here (2 cores), said before it starts;
# scripts/step.sh also says, when it ends, how long it took (and logs it to build/step-times.log).
say = @printf '\n== make: %s (about %s)\n' $(1) $(2)

.PHONY: all steps test test-fast deps build results paper document crosscheck hard-cases continuum rim-series liftoff kink own-scenes bench bench-large check-results clean help FORCE

# An interrupted recipe would have make delete its targets, the committed results among them. Every
# program writes its files whole (a temporary file, then rename), so what is there is never half
# written: keep it. It is older than the program that makes it, so the next make remakes it.
.PRECIOUS: $(wildcard results/* results/large/*)

# `make all` runs the steps that share no output side by side, one per core, the benchmarks among
# them, then the document, and ends with a table of what each step cost (scripts/step_report.sh).
# The steps go in two rounds: first what the penalty cross-check and the benchmarks read (the
# paper's table, Fig. 2's data, the contraction factors, the series' answer) beside the exact
# cross-check, then the rest, longest first. Within one round make -j starts a step whose inputs
# are still being made only after every step it queued meanwhile (a fresh clone's make all of
# 4fe1182 started the penalty cross-check 3 min in, and it ran alone for its last 3.4 min; one of
# c34c6ad's started the speed benchmark, which waited for the series' answer, after all the rest).
# The benchmarks used to run alone, after the rest, so that nothing would disturb their timings;
# but the two cores here are two cores, not two threads of one, and a process on one barely slows
# one on the other (plate -n 512 took 5.66 to 5.88 s alone and 5.61 to 5.79 s with a second beside
# it), while running them alone cost 6.3 min of one core idle. What would disturb them is a third
# process: in the pool the penalty cross-check runs its FreeFEM runs one at a time
# (PENALTY_JOBS=1), not one per core as it does when made on its own.
# The page's first screen quotes the run's time from rebuild_times.csv, which step_report.sh writes
# only at the end: the page is rendered once more then (seconds), or it would show the run before.
STEPS_FIRST := $(CROSSCHECK) $(FIG2_DATA) $(RIM_SERIES) $(TABLE_PAPER) $(CONTRACTION)
PENALTY_JOBS ?= $(JOBS)
ALL_START := $(shell date +%s)
all: build ## build, then every result, figure, benchmark and the document (the steps side by side on the cores found)
	@date +%s > $(BUILD)/.all-steps-start
	$(MAKE) --no-print-directory -j $(JOBS) --output-sync=target $(STEPS_FIRST)
	$(MAKE) --no-print-directory -j $(JOBS) --output-sync=target PENALTY_JOBS=1 steps
	$(MAKE) --no-print-directory paper
	@scripts/step_report.sh $$(( $$(date +%s) - $(ALL_START) )) $$(( $$(date +%s) - $$(cat $(BUILD)/.all-steps-start) ))
	@$(MAKE) --no-print-directory document > /dev/null

# Longest first (make -j starts prerequisites in the order they are listed; the times are this
# machine's: 5.4, 3.6, 2.9, 2.1, 1.8 min, then about a minute or less each); `bench` last, for its
# figures.
steps: crosscheck $(BENCH) $(TTA) $(TABLE_FINE) liftoff hard-cases results/micro_benchmarks.md continuum kink results own-scenes bench

help: ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 12

deps: ## install missing Debian packages (apt-get; root or sudo)
	@scripts/deps.sh

# First configuration only: cmake --build re-configures by itself when CMakeLists.txt changes.
$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# cmake --build is incremental: it relinks a program only when its sources changed, so the
# results that depend on a program are remade only then.
$(BINS) &: FORCE | deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

build: $(BINS) ## compile the solver, the plate program and the tests

test: build ## run the test suite (every label: unit, fine, program, freefem, document)
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

test-fast: build ## the unit tests alone, the mathematics (under 30 s here)
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -L unit

crosscheck: results/crosscheck.md $(CROSSCHECK_PENALTY) $(PENALTY_FIGURE) $(TABLE_FIGURE) ## FreeFEM (HCT, gmsh) against this code, exactly and by the paper's penalty method: results/crosscheck.md, results/crosscheck_penalty.md

$(CROSSCHECK) &: $(BUILD)/crosscheck reference/square_with_circle.geo reference/disk_with_punch.geo reference/contact_hct.edp reference/checked_solve.idp reference/mirror_quarter.idp reference/plate_constants.csv $(PAPER_NUMBERS) | deps
	scripts/step.sh "results/crosscheck.md: FreeFEM and this code on the square; FreeFEM on the disk" "30 s" $(BUILD)/crosscheck --out results --work $(BUILD)/crosscheck-work

# The penalty cross-check reads our table, contraction factors and Fig. 2 data from results/.
$(CROSSCHECK_PENALTY) &: $(BUILD)/crosscheck_penalty reference/square_with_circle.geo reference/quarter_square_with_circle.geo reference/penalty_hct.edp reference/contact_hct.edp reference/checked_solve.idp reference/mirror_quarter.idp \
                         reference/paper_table.csv reference/plate_constants.csv $(PAPER_NUMBERS) results/table.csv results/contraction.csv \
                         results/fig2.csv | deps
	scripts/step.sh "results/crosscheck_penalty.md: the FreeFEM penalty script against the table of the paper and this code at fixed eps and in Fig. 2" "4 min" $(BUILD)/crosscheck_penalty --out results --work $(BUILD)/crosscheck-penalty-work --jobs $(PENALTY_JOBS)
$(PENALTY_FIGURE): results/crosscheck_penalty_fig2.csv
$(TABLE_FIGURE): results/crosscheck_penalty_table.csv

hard-cases: results/hard_cases.md ## tiny eps, area and point contact, n = 512, every bad input: results/hard_cases.md

# It runs build/plate on every line of tests/bad_input.tsv, so it depends on both.
$(HARD_CASES) &: $(BUILD)/hard_cases $(BUILD)/plate tests/bad_input.tsv reference/plate_constants.csv
	scripts/step.sh "results/hard_cases.md: tiny eps; point and area contact; n = 512; every bad input" "2 min" $(BUILD)/hard_cases --out results --plate $(BUILD)/plate --cases tests/bad_input.tsv --scratch $(BUILD)/hard-cases-work

rim-series: $(RIM_SERIES) ## the paper's scene by the rim-contact series, the yardstick: results/rim_series.md (1 min)

$(RIM_SERIES) &: $(BUILD)/rim_series $(PAPER_NUMBERS)
	scripts/step.sh "results/rim_series.md: the rim-contact series at increasing truncations; the clamped square against it" "1 min" $(BUILD)/rim_series --out results

continuum: $(CONTINUUM) ## the h -> 0 limit: exact solves n = 8 ... 512, three samplings, orders, Richardson (about 1 min)

# The timings file is written by the same run; it is not byte-identical between runs.
$(CONTINUUM_DATA) &: $(BUILD)/continuum $(PAPER_NUMBERS)
	scripts/step.sh "results/continuum*: exact solves n = 8 ... 512 with three samplings" "1 min" $(BUILD)/continuum --out results

liftoff: $(LIFTOFF) ## scenes where the plate lifts off part of the rim: three kinds of rows, and FreeFEM on fitted meshes (about 2 min)

# The timings file is written by the same run; it is not byte-identical between runs.
$(LIFTOFF) &: $(BUILD)/liftoff reference/square_with_circle.geo reference/quarter_square_with_circle.geo reference/contact_hct.edp reference/checked_solve.idp reference/mirror_quarter.idp | deps
	scripts/step.sh "results/liftoff*: scenes where the plate lifts off part of the rim, and FreeFEM on fitted meshes" "2 min" $(BUILD)/liftoff --out results --work $(BUILD)/liftoff-work

kink: $(KINK) ## the plain space against the one that carries the kink at the rim (D31), three scenes against the series (about 40 s)

$(KINK_DATA) &: $(BUILD)/kink_study $(PAPER_NUMBERS)
	scripts/step.sh "results/kink*: the plain space and the kink carried (D31) on three scenes, against the series" "40 s" $(BUILD)/kink_study --out results

results/kink.svg results/kink.png: results/kink.csv

own-scenes: $(OWN_SCENES) ## the document's three worked plate commands on scenes of one's own, and what each prints (5 s)

$(OWN_SCENES): $(BUILD)/plate scripts/own_scenes.sh
	scripts/step.sh "results/own_scenes.md: three worked plate commands on scenes of one's own" "5 s" scripts/own_scenes.sh $(BUILD)/plate $@
results/continuum.svg results/continuum.png: results/continuum_error.csv
results/continuum_q.svg results/continuum_q.png: results/continuum_q.csv

results: $(RESULTS) ## the paper's table, Fig. 1, Fig. 2 and the contraction check, in results/

# Each driver writes its files whole (temporary file, then rename); gnuplot writes to a
# temporary file that is renamed once it is complete.
$(TABLE_PAPER) &: $(BUILD)/table reference/paper_table.csv $(PAPER_NUMBERS)
	scripts/step.sh "results/table.md: the paper's iteration table" "1 s" $(BUILD)/table --which paper --out results

$(TABLE_FINE) &: $(BUILD)/table reference/paper_table.csv $(PAPER_NUMBERS)
	scripts/step.sh "results/table_fine.md: the iteration table on finer grids" "2 min" $(BUILD)/table --which fine --out results

$(CONTRACTION) &: $(BUILD)/contraction $(PAPER_NUMBERS)
	scripts/step.sh "results/contraction.md: the measured contraction factors" "5 s" $(BUILD)/contraction --out results

$(FIG1_DATA) &: $(BUILD)/fig1 $(PAPER_NUMBERS)
	scripts/step.sh "Fig. 1 data" "5 s" $(BUILD)/fig1 --out results

$(FIG2_DATA) &: $(BUILD)/fig2 $(PAPER_NUMBERS)
	scripts/step.sh "Fig. 2 data" "1 min" $(BUILD)/fig2 --out results

results/fig1.svg results/fig1.png: $(FIG1_DATA)
results/fig2.svg results/fig2.png: $(FIG2_DATA)
results/contraction.svg results/contraction.png results/linear_history.svg results/linear_history.png: $(CONTRACTION)
$(RIM_FIGURE): results/crosscheck_rim.csv
results/%.svg: paper/figures/%.gp | deps
	gnuplot -e "fmt='svg'; out='$@.tmp'" $< && mv $@.tmp $@
results/%.png: paper/figures/%.gp | deps
	gnuplot -e "fmt='png'; out='$@.tmp'" $< && mv $@.tmp $@

bench: $(BENCH_ALL) ## speed against error up to n = 512 with PETSc's SNESVI, time to accuracy with FreeFEM, micro-benchmarks (about 6 min)

# Timings differ on every run: these files are remade only when the programs change.
$(BENCH) &: $(BUILD)/bench $(BUILD)/peer_snesvi $(PAPER_NUMBERS) results/rim_answer.csv
	scripts/step.sh "results/speed_vs_error*: every solver and PETSc's SNESVI to n = 512 in a process of its own" "3.5 min" $(BUILD)/bench --answer results/rim_answer.csv --out results

# The grid n = 1024 shows scale alone and took about as long as the rest of bench and more than
# twice its memory (15 GiB): run on request, not by `make all`; its files are committed apart and
# the document names them. Without them the document cannot be built: say which target makes them.
bench-large: build results/rim_answer.csv ## the exact solver at n = 1024 alone (3 min, 15 GiB): results/large/ (not part of make all)
	$(call say,"results/large/speed_vs_error*: the exact solver at n = 1024","3 min")
	mkdir -p results/large
	$(BUILD)/bench --answer results/rim_answer.csv --min-n 1024 --max-exact 1024 --out results/large
$(BENCH_LARGE):
	@echo "$@ is missing: make bench-large writes it (the grid n = 1024 alone: 3 min, 15 GiB)" >&2; exit 1

# Through step.sh, so that its time is in rebuild_times.csv with the other steps'.
results/micro_benchmarks.md: $(BUILD)/micro_bench
	scripts/step.sh "results/micro_benchmarks.md: the three kernels timed by Google Benchmark" "20 s" \
	  bash -c '{ echo "\`\`\`"; "$$1" --benchmark_color=false 2>&1; echo "\`\`\`"; } > "$$2.tmp" && mv "$$2.tmp" "$$2"' _ $(BUILD)/micro_bench $@

results/speed_vs_error.svg results/speed_vs_error.png: $(BENCH)

# The whole plate process against the continuum limit; timings differ on every run.
$(TTA) &: $(BUILD)/time_to_accuracy $(BUILD)/plate $(BUILD)/peer_snesvi results/rim_answer.csv reference/square_with_circle.geo reference/quarter_square_with_circle.geo reference/contact_hct.edp reference/checked_solve.idp reference/mirror_quarter.idp
	scripts/step.sh "results/time_to_accuracy*: whole plate/SNESVI/FreeFEM runs against the continuum limit" "3 min" $(BUILD)/time_to_accuracy --plate $(BUILD)/plate --answer results/rim_answer.csv --out results

results/time_to_accuracy.svg results/time_to_accuracy.png: results/time_to_accuracy.csv

paper: results/paper.html ## the literate document: results/paper.html (self-contained, opens offline); remakes stale results first

# A fresh clone's programs are newer than the results it carries, so `make paper` would remake
# them all (about 17 minutes). This renders the document from the results as they are.
document: $(BUILD)/prose_numbers $(BUILD)/render_report results/versions.csv | deps ## results/paper.html from the results/ present, remaking none of them (10 s)
	$(BUILD)/prose_numbers --out results
	$(render_paper)

# Every number the prose states, derived from the results above (paper/filters/numbers.lua fills them in).
results/versions.csv: scripts/deps.sh | deps
	@# A Debian epoch ("4:" in g++'s 4:12.2.0) is packaging, not the upstream version: drop it.
	@# The pipe hides dpkg-query's status, so the count of rows says whether every package was found.
	{ echo 'package,version'; dpkg-query -W -f='$${Package},$${Version}\n' $(VERSIONED) | sed 's/,[0-9]*:/,/'; } > $@.tmp
	@test $$(grep -c . $@.tmp) -eq $$(( $(words $(VERSIONED)) + 1 )) || { echo "versions.csv: dpkg-query did not find every package of VERSIONED" >&2; rm -f $@.tmp; exit 1; }
	mv $@.tmp $@

$(NUMBERS) &: $(BUILD)/prose_numbers $(RESULTS) $(RIM_SERIES) $(CONTINUUM_DATA) results/liftoff.csv results/kink.csv results/kink_stability.csv results/kink_polygon.csv $(CROSSCHECK) results/crosscheck_penalty_limits.csv $(HARD_CASES) $(BENCH) results/large/speed_vs_error.csv results/versions.csv \
               $(wildcard results/rebuild_times.csv) reference/plate_constants.csv
	$(BUILD)/prose_numbers --out results

define render_paper
	RENDER_REPORT=$(BUILD)/render_report pandoc paper/paper.md --from markdown --to html5 --standalone --self-contained --mathml \
	  --lua-filter paper/filters/numbers.lua \
	  --lua-filter paper/filters/equations.lua --lua-filter paper/filters/code.lua \
	  --lua-filter paper/filters/include.lua --lua-filter paper/filters/numbering.lua --css paper/style.css --include-after-body paper/print.html --resource-path . \
	  --toc --toc-depth 2 --output results/paper.html.tmp && mv results/paper.html.tmp results/paper.html
endef

results/paper.html: $(PAPER_INPUTS) | deps
	$(call say,"results/paper.html","10 s")
	$(render_paper)

# Each driver that writes a deterministic table, its files (the lists above, timings left out: they
# differ on every run), rebuilt into a scratch folder and compared with the committed ones number by
# number (build/compare_tables: one unit in the last printed digit), never byte for byte. `make test`
# runs the drivers that take seconds the same way.
CHECKED_DRIVERS := rim_series table contraction fig1 fig2 continuum liftoff kink_study crosscheck crosscheck_penalty
untimed = $(notdir $(filter-out %_timings.csv,$(1)))
CHECKED_table              := $(call untimed,$(TABLES))
CHECKED_contraction        := $(call untimed,$(CONTRACTION))
CHECKED_fig1               := $(call untimed,$(FIG1_DATA))
CHECKED_fig2               := $(call untimed,$(FIG2_DATA))
CHECKED_continuum          := $(call untimed,$(CONTINUUM_DATA))
CHECKED_crosscheck         := $(call untimed,$(CROSSCHECK))
CHECKED_crosscheck_penalty := $(call untimed,$(CROSSCHECK_PENALTY))
CHECKED_rim_series         := $(call untimed,$(RIM_SERIES))
CHECKED_liftoff            := $(call untimed,$(LIFTOFF))
CHECKED_kink_study         := $(call untimed,$(KINK_DATA))
CHECK_DIR := $(BUILD)/check-results
comma := ,
empty :=
space := $(empty) $(empty)

check-results: build ## rebuild every deterministic table into build/check-results and compare it with results/ (about 9 min)
	$(call say,"check-results: $(CHECKED_DRIVERS) rebuilt and compared with results/","9 min")
	@rm -rf $(CHECK_DIR); status=0; \
	for spec in $(foreach d,$(CHECKED_DRIVERS),$(d):$(subst $(space),$(comma),$(CHECKED_$(d)))); do \
	  d=$${spec%%:*}; files=$$(echo "$${spec#*:}" | tr , ' '); \
	  mkdir -p $(CHECK_DIR)/$$d; \
	  extra=; case $$d in crosscheck*|liftoff) extra="--work $(CHECK_DIR)/$$d-work";; esac; \
	  echo "== $$d"; \
	  $(BUILD)/$$d --out $(CHECK_DIR)/$$d $$extra > $(CHECK_DIR)/$$d.log 2>&1 \
	    || { echo "$$d failed (exit $$?); its output is in $(CHECK_DIR)/$$d.log"; status=1; continue; }; \
	  $(BUILD)/compare_tables --expected results --rebuilt $(CHECK_DIR)/$$d $$files || status=1; \
	done; \
	if [ $$status = 0 ]; then echo "check-results: every table agrees with results/"; \
	else echo "check-results: some tables differ (above)"; exit 1; fi

clean: ## remove build products (not results/)
	rm -rf $(BUILD)

FORCE:
