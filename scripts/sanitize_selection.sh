# The cases scripts/sanitize.sh runs under AddressSanitizer and UBSan (sourced; scripts/claims.py
# reads the same lines to count them). One assignment a line: NAME="regex" or NAME+="regex".
#
# modules: every case of the modules below the commands (tests/CMakeLists.txt labels each with its
# executable) but `slow`: those over 10 s under ASan for a finite-volume reference solve or a whole
# ES run (the kernels they call run in the cases kept; 400 s of thermal's and 120 s of run's 670 s
# serial, measured at 4efedea). no_allocation_tests replaces operator new and delete, which ASan
# must own (an alloc-dealloc mismatch at exit): Release only.
modules="^(geometry|mesh|voxel|thermal|opt|run|mold|io|store|serve)_tests$"
slow="read a coupled cup|see a plate-shaped void|shape factor converges|core keeps the heat|thin shell's outer edge"
slow+="|reference block at 1 mm meets|isothermal face has S|void plane: the line sinks see the plate|surface spread against the FEM"
slow+="|through a cavity void's wall matches|infeasible children of feasible parents|ranks an infeasible layout as its penalty"
# others: every case of the other executables (eval, cli, report, the scripted ones) but `heavy`:
# those over 30 s under ASan (a whole pipeline, finite volumes, several optimisations; measured
# at 67c457a, 30 min serial for all of them), the MPI ranks and the installed tree (scripted
# around the Release build), the browser tests (chromium's own memory), and no_allocation_tests
# (it replaces operator new, which ASan owns).
heavy="coolant rise: warmer coolant|coolant rise: the finite volumes|cost_per_part|local wall:|across the part:"
heavy+="|coupled cavity: a wall the part cannot|coupled cavity: the optimiser's cycle|coupled cavity: every bundled mold"
heavy+="|coupled cavity: the (cup|gear|L-bracket)'s samples|baffle's coolant warms"
heavy+="|mtcs replay: the run keeps its mold|mtcs bench thermal on a mold: the tau|summary.json gives each circuit"
heavy+="|mtcs bench part:|every bundled mold's best keeps|report: each violated clearance|report: the cavity temperature equals"
heavy+="|report: each bore entry|report: the anytime curves|report: a missing run|report and export of an SMS-EMOA run"
heavy+="|default objectives: taking a circuit away"
heavy+="|distance queries do not allocate|islands on MPI|install:|chromium"
