# dyncontact_light_optimisation(target): the target's own sources at -O1 in Release builds.
# For code whose run time is spent in the solvers it calls (the case readers, the runs, the
# writers, the command line, the Python binding, the tests): -O3 there costs compile time
# (templates of nlohmann JSON, CLI11, pybind11, GoogleTest instantiated and optimised) and saves
# no measurable run time. The solver libraries (core, nlp, dynamics) keep the build's level.
# Without fast-math flags -O1 and -O3 compute the same floating-point results
# (scripts/check_same_results.sh compares the examples' files between two builds).
function(dyncontact_light_optimisation target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()
