# DRILLFLEX_FUZZ: every layer is compiled for libFuzzer (clang's -fsanitize=fuzzer-no-link: the
# coverage counters the fuzzer steers by) with AddressSanitizer and UndefinedBehaviorSanitizer, and
# fuzz/ adds one executable per reader (drillflex_add_fuzzer, fuzz/CMakeLists.txt). scripts/fuzz
# configures it in build-fuzz/ and runs the targets.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "DRILLFLEX_FUZZ needs clang (libFuzzer): configure with CXX=clang++ (scripts/fuzz does)")
endif()
if(DRILLFLEX_SANITIZE)
  message(FATAL_ERROR "DRILLFLEX_FUZZ brings its own sanitizers: leave DRILLFLEX_SANITIZE off")
endif()
# A layer that the targets link but never call (fuzz/CMakeLists.txt marks it DRILLFLEX_FUZZ_LINK_ONLY:
# the solvers, reached through the model's dependency, and the analyses, through io's) compiles at -O0
# without instrumentation: half the build's time, for code no input runs.
set(instrumented "$<NOT:$<BOOL:$<TARGET_PROPERTY:DRILLFLEX_FUZZ_LINK_ONLY>>>")
target_compile_options(drillflex_options INTERFACE
  "$<${instrumented}:-fsanitize=fuzzer-no-link,address,undefined;-fno-sanitize-recover=undefined;-fno-omit-frame-pointer>"
  "$<$<NOT:${instrumented}>:-O0>")
target_link_options(drillflex_options INTERFACE -fsanitize=address,undefined)
# As in the DRILLFLEX_SANITIZE build (CMakeLists.txt): one Eigen allocation rule for every TU.
target_compile_definitions(drillflex_options INTERFACE EIGEN_MALLOC_ALREADY_ALIGNED=0)
