# Included from tests/CMakeLists.txt: registers fuzz.build and one fuzz.<parser> test per target,
# each running libFuzzer for CAMWB_FUZZ_SECONDS from a seed corpus of the repository's own inputs
# (goldens, post outputs, CL files). A finding fails the test and leaves the crashing input in
# the build folder (libFuzzer prints its path). Needs clang with libFuzzer (libclang-rt-14-dev).
set(CAMWB_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzz.<parser> test runs libFuzzer")
find_program(CLANGXX NAMES clang++ clang++-14)
file(GLOB libfuzzer /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a)
if(NOT CLANGXX OR NOT libfuzzer)
  message(WARNING "clang++ with libFuzzer not found: the fuzz.* tests are not registered (scripts/install-deps.sh installs them)")
  return()
endif()
set(fuzz_dir ${CMAKE_BINARY_DIR}/fuzz)
add_test(NAME fuzz.build
  COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR}/tests/fuzz -DBINARY=${fuzz_dir} -DCLANGXX=${CLANGXX}
          -P ${PROJECT_SOURCE_DIR}/tests/fuzz/BuildFuzz.cmake)
set_tests_properties(fuzz.build PROPERTIES FIXTURES_SETUP fuzz_targets LABELS fuzz TIMEOUT 1200)

set(seeds_sinumerik ${PROJECT_SOURCE_DIR}/tests/golden/nc/sinumerik ${PROJECT_SOURCE_DIR}/posts/sinumerik828d-emco/tests
                    ${PROJECT_SOURCE_DIR}/posts/sinumerik840d/tests)
set(seeds_heidenhain ${PROJECT_SOURCE_DIR}/tests/golden/nc/heidenhain)
set(seeds_iso ${PROJECT_SOURCE_DIR}/tests/golden/nc/iso ${PROJECT_SOURCE_DIR}/posts/linuxcnc/tests)
set(seeds_apt ${PROJECT_SOURCE_DIR}/tests/data/cl)
set(seeds_freecaddump ${PROJECT_SOURCE_DIR}/tests/data/cl)
set(seeds_trace ${PROJECT_SOURCE_DIR}/posts/linuxcnc/tests)
foreach(name IN ITEMS sinumerik heidenhain iso apt freecaddump trace)
  # Seed folders hold their files in case subfolders: libFuzzer reads one level, so list them.
  set(corpus "")
  foreach(seed IN LISTS seeds_${name})
    file(GLOB_RECURSE seed_files LIST_DIRECTORIES false ${seed}/*)
    foreach(f IN LISTS seed_files)
      get_filename_component(parent ${f} DIRECTORY)
      list(APPEND corpus ${parent})
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES corpus)
  file(MAKE_DIRECTORY ${fuzz_dir}/corpus-${name} ${fuzz_dir}/findings-${name})
  add_test(NAME fuzz.${name}
    COMMAND ${fuzz_dir}/fuzz_${name} -max_total_time=${CAMWB_FUZZ_SECONDS} -timeout=10 -rss_limit_mb=2048
            -max_len=65536 -print_final_stats=1 -artifact_prefix=${fuzz_dir}/findings-${name}/
            ${fuzz_dir}/corpus-${name} ${corpus})
  set_tests_properties(fuzz.${name} PROPERTIES FIXTURES_REQUIRED fuzz_targets LABELS fuzz
                       TIMEOUT 600 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1;UBSAN_OPTIONS=print_stacktrace=1")
endforeach()
