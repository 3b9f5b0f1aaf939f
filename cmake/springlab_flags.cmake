# Compiler flags shared by every Springlab target.

# warnings: every target links springlab_warnings; CI turns them into errors
add_library(springlab_warnings INTERFACE)
target_compile_options(springlab_warnings INTERFACE -Wall -Wextra -Wpedantic
                       $<$<BOOL:${SPRINGLAB_WERROR}>:-Werror>)

# determinism: results must not depend on build flags, so no fast-math and no FMA contraction
# (a fused multiply-add rounds once where the source rounds twice, which changes the bits)
add_compile_options(-ffp-contract=off -fno-fast-math)

# sanitizers for the whole build: -DSPRINGLAB_SANITIZE=address,undefined or =thread
if(SPRINGLAB_SANITIZE)
  if(SPRINGLAB_SANITIZE MATCHES "thread" AND SPRINGLAB_SANITIZE MATCHES "address")
    message(FATAL_ERROR "SPRINGLAB_SANITIZE: thread cannot be combined with address")
  endif()
  add_compile_options(-fsanitize=${SPRINGLAB_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${SPRINGLAB_SANITIZE})
endif()

# the sanitizer builds: every program keeps Mesa's software driver loaded to the end (see the file);
# executables link it with springlab_sanitizer_support(<target>)
if(SPRINGLAB_SANITIZE MATCHES "thread|address")
  add_library(springlab_keep_gl_driver OBJECT ${PROJECT_SOURCE_DIR}/tests/sanitizers/keep_gl_driver_loaded.cpp)
  target_link_libraries(springlab_keep_gl_driver PUBLIC ${CMAKE_DL_LIBS})
endif()
function(springlab_sanitizer_support target)
  if(TARGET springlab_keep_gl_driver)
    target_link_libraries(${target} PRIVATE springlab_keep_gl_driver)
  endif()
endfunction()

# fuzzing (tests/fuzz): coverage for libFuzzer everywhere, and the sanitizers that turn a bad read
# into a crash it can save; the fuzzer executables add libFuzzer's own main when they link
if(SPRINGLAB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SPRINGLAB_FUZZ needs clang (libFuzzer), not ${CMAKE_CXX_COMPILER_ID}: configure a "
                        "fresh build folder with CXX=clang++-14, or run tools/fuzz.sh, which does")
  endif()
  if(SPRINGLAB_SANITIZE)
    message(FATAL_ERROR "SPRINGLAB_FUZZ already builds with address,undefined: leave SPRINGLAB_SANITIZE empty")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# unity builds of the libraries and the larger programs: their sources compiled a few at a time as
# one translation unit, so that Qt's and Eigen's headers are parsed once a batch rather than once a
# file (the build's main cost). Off to find a file that does not compile on its own.
option(SPRINGLAB_UNITY_BUILD "Compile the libraries' sources in batches (unity build)" ON)
function(springlab_unity_build target)
  if(SPRINGLAB_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
