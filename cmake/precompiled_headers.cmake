# How the project's own programs are compiled: precompiled headers for the
# tests, examples, benchmarks and tool, unity builds for the tests, tool and
# Python module, and a lighter optimization level for the tests and
# examples. None of these applies to the library, which users link, nor to
# anything a user builds.
#
# Parsing <cgogn/cgogn.h> costs about 4 s per translation unit, GoogleTest's
# header 1 s more: a precompiled header parses them once per build. Each kind
# of program reuses one header compiled by a small object library with the
# same flags (REUSE_FROM). A target with other code-generation flags (-fPIC,
# the peers' -frounding-math) gets none.
#
# The tests and examples check results, not speed: in every build type but
# Debug they are compiled at CGOGN_TEST_OPTIMIZATION (-Og: the release
# build's tests take 213 s of compiler time at -Og, 263 s at -O1, a third
# more at -O3, and the suite runs in 50 s either way, its work being in the
# library) and call the library compiled with the build type's flags. The
# asan preset sets -O1: the randomized tests instantiate the traversals and
# checks they run in their own files, and unoptimized under the sanitizers
# they made the suite 2,134 s of test time (1,106 s on 2 cores) against 677 s
# (386 s) at -O1, for 602 s more compiler time.
# The benchmarks and the tool keep the build type's flags.
option(CGOGN_PRECOMPILED_HEADERS "Precompile <cgogn/cgogn.h> (and gtest) for the tests, examples, benchmarks and tool" ON)
# Unity builds: the files of one program are compiled a batch at a time, as
# one unit, so that the traversals, operators, readers and checks they share
# are instantiated and optimized once per unit instead of once per file:
# - the test files of each test executable, eight at a time (four core test
#   files: 7.6 s as one unit, 12.7 s apart). Each test file keeps its names
#   in a namespace of its own (cgogn_<file name>) so that they do not collide;
# - the tool's commands, all in one unit (79 s of compiler time apart, 23 s
#   together: each command instantiates the same readers and writers);
# - the Python module's bindings, in two units (117 s apart, 80 s in two units of four).
option(CGOGN_UNITY_BUILD "Compile the tests, the tool and the Python module in batches (unity builds)" ON)
set(CGOGN_TEST_OPTIMIZATION "-Og" CACHE STRING
    "Optimization flag of the tests and examples in every build type but Debug (empty: the build type's)")

# Some test files take long to compile and little to run: they instantiate a
# traversal or check for every dimension and map type, on small meshes. Where
# the tests are optimized for the sake of the randomized ones (the asan
# preset), such files are compiled at CGOGN_QUICK_TEST_OPTIMIZATION instead
# (the asan preset: -O0; empty: as the other tests). With the sanitizers, the
# seven files named in tests/CMakeLists.txt take 398 s of compiler time at
# -O1, each alone, and their tests 12 s to run; at -O0, their tests take
# 31 s.
set(CGOGN_QUICK_TEST_OPTIMIZATION "" CACHE STRING
    "Optimization flag of the test files that are long to compile and quick to run (empty: the tests')")

# cgogn_quick_test_files(target file...): the files of target, long to compile
# and quick to run, are compiled at CGOGN_QUICK_TEST_OPTIMIZATION when it is
# set. Each is then compiled alone, without the precompiled header (made at
# the other tests' level, which a compiler refuses to mix).
function(cgogn_quick_test_files target)
  if(NOT CGOGN_QUICK_TEST_OPTIMIZATION)
    return()
  endif()
  set_property(SOURCE ${ARGN} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS
                                                        $<$<NOT:$<CONFIG:Debug>>:${CGOGN_QUICK_TEST_OPTIMIZATION}>)
  set_property(SOURCE ${ARGN} TARGET_DIRECTORY ${target} PROPERTY SKIP_PRECOMPILE_HEADERS ON)
  set_property(SOURCE ${ARGN} TARGET_DIRECTORY ${target} PROPERTY SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()

set(_cgogn_pch_headers <cgogn/cgogn.h> <algorithm> <array> <cmath> <cstdint> <filesystem> <functional> <map>
                       <memory> <numeric> <random> <set> <string> <unordered_map> <utility> <vector>)

# cgogn_optimize_as_test(target): the tests' optimization level in optimized
# builds (Release, RelWithDebInfo, MinSizeRel; Debug keeps its own).
function(cgogn_optimize_as_test target)
  if(CGOGN_TEST_OPTIMIZATION)
    target_compile_options(${target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:${CGOGN_TEST_OPTIMIZATION}>)
  endif()
endfunction()

# cgogn_unity_build(target batch_size): compiles target's sources
# batch_size at a time (0: all in one unit) when CGOGN_UNITY_BUILD is on.
function(cgogn_unity_build target batch_size)
  if(CGOGN_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch_size})
  endif()
endfunction()

# cgogn_use_precompiled_headers(target [GTEST] [TEST]): gives target the
# precompiled <cgogn/cgogn.h> (and <gtest/gtest.h> with GTEST). TEST: target
# is a test or example (cgogn_optimize_as_test is applied to it, and its
# header is compiled likewise). The target must link cgogn::cgogn (and
# GTest::gtest) and take the project's warnings.
function(cgogn_use_precompiled_headers target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "GTEST;TEST" "" "")
  if(arg_TEST)
    cgogn_optimize_as_test(${target})
  endif()
  if(arg_TEST AND arg_GTEST)
    cgogn_unity_build(${target} 8)
  endif()
  if(NOT CGOGN_PRECOMPILED_HEADERS)
    return()
  endif()
  set(donor cgogn_pch)
  if(arg_GTEST)
    string(APPEND donor _gtest)
  endif()
  if(arg_TEST)
    string(APPEND donor _test)
  endif()
  if(NOT TARGET ${donor})
    set(source ${PROJECT_BINARY_DIR}/${donor}.cpp)
    if(NOT EXISTS ${source})
      file(WRITE ${source} "// compiles the precompiled header of ${donor}\n")
    endif()
    add_library(${donor} OBJECT EXCLUDE_FROM_ALL ${source})
    target_link_libraries(${donor} PRIVATE cgogn::cgogn)
    set(headers ${_cgogn_pch_headers})
    if(arg_GTEST)
      target_link_libraries(${donor} PRIVATE GTest::gtest)
      list(APPEND headers <gtest/gtest.h>)
    endif()
    target_precompile_headers(${donor} PRIVATE ${headers})
    cgogn_set_warnings(${donor})
    if(arg_TEST)
      cgogn_optimize_as_test(${donor})
    endif()
  endif()
  target_precompile_headers(${target} REUSE_FROM ${donor})
endfunction()
