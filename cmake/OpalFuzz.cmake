# Sanitizer flags of the fuzz build (OPAL_FUZZ=ON). Every Opal source compiled in that
# build is instrumented for libFuzzer's coverage and checked by AddressSanitizer and
# UndefinedBehaviorSanitizer; the fuzz executables add libFuzzer's main. Any undefined
# behaviour stops the run (-fno-sanitize-recover), so libFuzzer reports it as a crash.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "OPAL_FUZZ needs clang (Debian packages clang, libfuzzer-14-dev, libclang-rt-14-dev): "
    "CC=clang CXX=clang++ cmake -S . -B build-fuzz -DOPAL_FUZZ=ON")
endif()

# Build type Debug (scripts/fuzz): assertions stay on and count as findings; -O1 keeps
# the build short and the runs fast.
set(OPAL_SANITIZERS address,undefined)
add_compile_options(-O1 -fsanitize=fuzzer-no-link,${OPAL_SANITIZERS} -fno-sanitize-recover=all
  -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=${OPAL_SANITIZERS})

include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_FLAGS -fsanitize=fuzzer)
check_cxx_source_compiles([[
  #include <cstddef>
  #include <cstdint>
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]] OPAL_HAVE_LIBFUZZER)
unset(CMAKE_REQUIRED_FLAGS)
if(NOT OPAL_HAVE_LIBFUZZER)
  message(FATAL_ERROR "clang cannot link libFuzzer: install the Debian packages libfuzzer-14-dev and "
    "libclang-rt-14-dev (or run scripts/setup)")
endif()
