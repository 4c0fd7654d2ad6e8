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
target_compile_options(drillflex_options INTERFACE
  -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
target_link_options(drillflex_options INTERFACE -fsanitize=address,undefined)
# As in the DRILLFLEX_SANITIZE build (CMakeLists.txt): one Eigen allocation rule for every TU.
target_compile_definitions(drillflex_options INTERFACE EIGEN_MALLOC_ALREADY_ALIGNED=0)
