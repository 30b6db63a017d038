# Common flags for every hilrig target, and small helpers so each folder's
# CMakeLists.txt says only what it builds and what it depends on.

add_library(hilrig_flags INTERFACE)
target_compile_options(hilrig_flags INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual
  -Wdouble-promotion -Wimplicit-fallthrough)
if(HILRIG_WERROR)
  target_compile_options(hilrig_flags INTERFACE -Werror)
endif()
if(HILRIG_COMPRESS_DEBUG)
  # Debug sections are ~95 % of a test binary and every test links the whole rig statically:
  # zlib-compressed they take a third of the disk (a clean `make test` once ran out of it). gdb,
  # addr2line and the sanitizers' symbolizer read them as they are.
  target_compile_options(hilrig_flags INTERFACE -gz)
  target_link_options(hilrig_flags INTERFACE -gz)
endif()
if(HILRIG_SANITIZE)
  target_compile_options(hilrig_flags INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(hilrig_flags INTERFACE -fsanitize=address,undefined)
  # GCC 12 reports false "maybe uninitialized" inside libstdc++ (std::function in std::regex)
  # once ASan instruments it; the optimised build keeps the warning.
  target_compile_options(hilrig_flags INTERFACE -Wno-maybe-uninitialized)
endif()
if(HILRIG_FUZZ)
  # Every library the fuzzers link is instrumented for coverage and checked by ASan+UBSan; the
  # fuzzers themselves add libFuzzer's main (fuzz/CMakeLists.txt).
  target_compile_options(hilrig_flags INTERFACE
    -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(hilrig_flags INTERFACE -fsanitize=address,undefined)
endif()
target_include_directories(hilrig_flags INTERFACE ${PROJECT_SOURCE_DIR})

# hilrig_static_runtime(TARGET): libstdc++ and libgcc linked into an executable (HILRIG_STATIC_RUNTIME).
# With fmt and toml++ compiled in (deps/), nothing else loads libstdc++.so: its ~2,700 symbol
# relocations and the loading of two more shared libraries were most of `hilrig --version`'s
# cost (docs/PERFORMANCE.md, "Fixed cost of a run"). Not with ASan/UBSan or libFuzzer: their
# runtimes replace operator new/delete and expect the shared libstdc++.
function(hilrig_static_runtime target)
  if(HILRIG_STATIC_RUNTIME AND NOT HILRIG_SANITIZE AND NOT HILRIG_FUZZ)
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
  endif()
endfunction()

# hilrig_library(NAME SOURCES ... DEPS ...)
function(hilrig_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_SOURCES)
    # A folder whose sources are globbed may be empty while it is being written.
    message(STATUS "hilrig: ${name} has no sources yet; not built")
    return()
  endif()
  add_library(${name} STATIC ${ARG_SOURCES})
  target_link_libraries(${name} PUBLIC hilrig_flags ${ARG_DEPS})
endfunction()

# hilrig_test(NAME SOURCES ... DEPS ... [COST SECONDS]): one GoogleTest executable, tests
# discovered by ctest. COST: about how long its slowest test takes under ASan, so that a clean
# tree's ctest (no timings recorded yet) starts it first instead of leaving it for the tail.
function(hilrig_test name)
  cmake_parse_arguments(ARG "" "COST" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(STATUS "hilrig: ${name} has no sources yet; not built")
    return()
  endif()
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE hilrig_flags ${ARG_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  if(HILRIG_UNITY_TESTS)
    set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${HILRIG_UNITY_TEST_BATCH})
  endif()
  # Project root and shared/ (the spec digests) are visible to tests as compile-time paths,
  # never hard-coded machine paths.
  target_compile_definitions(${name} PRIVATE
    HILRIG_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    HILRIG_BINARY_DIR="${PROJECT_BINARY_DIR}")
  include(GoogleTest)
  set(cost 0)
  if(ARG_COST)
    set(cost ${ARG_COST})
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300 COST ${cost})
endfunction()

# hilrig_bench(NAME SOURCES ... DEPS ...)
function(hilrig_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE hilrig_flags ${ARG_DEPS} benchmark::benchmark)
endfunction()

# Adds every immediate subfolder of the current folder that has a CMakeLists.txt,
# so a new device or driver folder joins the build without editing its parent.
function(hilrig_add_subfolders)
  file(GLOB children LIST_DIRECTORIES true RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT children)
  foreach(child ${children})
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${child} AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${child}/CMakeLists.txt)
      add_subdirectory(${child})
    endif()
  endforeach()
endfunction()
