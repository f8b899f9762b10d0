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
# commands: of the other executables (eval, cli, report: whole pipelines or the mtcs binary, minutes
# under ASan) the cases that read user input or stress a kernel, but `skip` (the plate's finite
# volumes at 4 mm: 70 s under ASan; the blind bores' film and drop run in the cases kept).
commands="CSV|mutated|bad numbers|run store faults|mesh reader|hypervolume|mtcs distance|mtcs evaluate|stiff|segments|circle|mold spec|layout|pipeline|meshes|cylinder-triangle|cylinder vs box|triangle-triangle|interference:|mtcs clearance|mtcs interfere|mtcs thermal|thermal spec|wall thickness|part sides|disk cache|panel matrix|hydraulics|coolant rise: the line sinks|coolant constraints|design rules|baffle:|bubbler:|blind bore:|molding over a whole face|access-map (rewrites|errors|MESH)"
skip="baffle's coolant warms"
