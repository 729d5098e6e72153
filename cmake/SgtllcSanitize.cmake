# Sanitizer and fuzzing builds (README "Reliability checks"; `make test-sanitize`, `make test-tsan`, `make fuzz`).
# Both apply to every target of the project, so the library, the tests and the command-line tool the tests run
# are instrumented alike. Clang only: libFuzzer ships with clang, and a GCC -O2 ASan build missed a use-after-free
# in the simulator that clang at -O1 reports.
set(SGTLLC_SANITIZE "" CACHE STRING
    "Sanitizers for every target, as for -fsanitize=: address,undefined or thread (clang; empty: none)")
option(SGTLLC_FUZZ "Build the libFuzzer harnesses of fuzz/ (clang; implies SGTLLC_SANITIZE=address,undefined)" OFF)

if(SGTLLC_FUZZ AND NOT SGTLLC_SANITIZE)
  set(SGTLLC_SANITIZE "address,undefined" CACHE STRING "" FORCE)
endif()

if(SGTLLC_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SGTLLC_SANITIZE and SGTLLC_FUZZ need clang: configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "(Debian packages clang and libclang-rt-14-dev; scripts/install-deps.sh --dev)")
  endif()
  # -O1 keeps the reports' stacks readable and the run fast enough for CI; the last -O on the line wins over the
  # build type's. Frame pointers give ASan and TSan full stacks at no unwinding cost. A report needs file and line
  # only: line tables instead of full debug information (-g) keep the instrumented trees to a fraction of the disk,
  # which matters because every test program links the whole library (a full -g ASan tree took 3.5 GB).
  add_compile_options(-fsanitize=${SGTLLC_SANITIZE} -O1 -gline-tables-only -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${SGTLLC_SANITIZE})
  if(SGTLLC_SANITIZE MATCHES "undefined")
    # Undefined behaviour stops the program like an ASan report instead of printing and going on.
    add_compile_options(-fno-sanitize-recover=all)
  endif()
endif()

if(SGTLLC_FUZZ)
  # Coverage feedback for libFuzzer in every library; the harnesses themselves link -fsanitize=fuzzer (fuzz/).
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
